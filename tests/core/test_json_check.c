/* The JSON gate (core/files/json_check.h): it accepts RFC 8259 texts within the
 * limits (and cJSON, an independent parser, parses each of them), and
 * refuses everything else with the problem at the right line and column —
 * including the two crafted inputs of issue 21: 100,000 nested arrays, and
 * invalid UTF-8 at column 631. */
#include <cjson/cJSON.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/json_check.h"
#include "tests/check.h"

static int accepted(const char *text, size_t length, json_limits limits)
{
    gt_error e;
    const int ok = json_check(text, length, limits, "t.json", &e) == 0;
    if (!ok)
        fprintf(stderr, "  (refused: %s)\n", e.message);
    return ok;
}

/* json_check accepts text, and so does cJSON (after a byte-order mark). */
static void check_valid(const char *text)
{
    const size_t n = strlen(text), bom = json_bom_length(text, n);
    CHECK_MSG(accepted(text, n, json_limits_cjson), "%s", text);
    cJSON *root = cJSON_ParseWithLengthOpts(text + bom, n - bom + 1, NULL, 1); /* the NUL included */
    CHECK_MSG(root != NULL, "cJSON refuses %s", text);
    cJSON_Delete(root);
}

/* json_check refuses text[0, n) with exactly `expected` as the message. */
static void check_invalid_n(const char *text, size_t n, json_limits limits, const char *expected)
{
    gt_error e = {{0}};
    CHECK_MSG(json_check(text, n, limits, "t.json", &e) == -1, "accepted %.60s", text);
    CHECK_MSG(strcmp(e.message, expected) == 0, "\n  got      '%s'\n  expected '%s'", e.message, expected);
}

static void check_invalid(const char *text, const char *expected)
{
    check_invalid_n(text, strlen(text), json_limits_gltf, expected);
}

static char *nested_arrays(int depth)
{
    char *text = malloc(2 * (size_t)depth + 1);
    memset(text, '[', (size_t)depth);
    memset(text + depth, ']', (size_t)depth);
    text[2 * depth] = '\0';
    return text;
}

static void test_valid_texts(void)
{
    static const char *const texts[] = {
        "{}", "[]", " 0 ", "-0", "-0.5e+10", "1E-3", "123456789012345678901234567890", "true", "false", "null",
        "\"\"", "\"a\\\"\\\\\\/\\b\\f\\n\\r\\t\\u00e9\"", "\"\\ud83d\\ude00\"",
        "\"\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80\"",
        "\xEF\xBB\xBF{\"a\":1}", "{\"a\":[1,{\"b\":null}],\"c\":\"d\"}\r\n\t ", "\"\x7f\"",
        "1.7976931348623157e308", "4.9e-324", "1e-400"};
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; ++i)
        check_valid(texts[i]);
}

static void test_syntax_errors(void)
{
    check_invalid("", "t.json: JSON text ends where a value was expected at line 1, column 1");
    check_invalid("[1,2", "t.json: JSON text ends early: an array or object is not closed at line 1, column 5");
    check_invalid("{\"a\":1,}", "t.json: expected a member name (a string), found '}' at line 1, column 8");
    check_invalid("[1,]", "t.json: expected a JSON value (true, false or null?), found ']' at line 1, column 4");
    check_invalid("{\"a\" 1}", "t.json: expected ':' after a member name, found '1' at line 1, column 6");
    check_invalid("{\n  \"a\": [1,\n  2 3]}",
                  "t.json: expected ',' or ']' after an array element, found '3' at line 3, column 5");
    check_invalid("{} x", "t.json: expected nothing after the JSON value, found 'x' at line 1, column 4");
    check_invalid("01", "t.json: expected nothing after the JSON value, found '1' at line 1, column 2");
    check_invalid("tru", "t.json: expected a JSON value (true, false or null?), found 't' at line 1, column 1");
    check_invalid("\"abc", "t.json: JSON string never closed; it starts at line 1, column 1");
    check_invalid_n("[0,\0]", 5, json_limits_gltf,
                    "t.json: expected a JSON value (true, false or null?), found byte 0x00 at line 1, column 4");
}

static void test_numbers(void)
{
    check_invalid("-", "t.json: invalid number (a digit must follow '-') at line 1, column 1");
    check_invalid("[1.]", "t.json: invalid number (a digit must follow the decimal point) at line 1, column 2");
    check_invalid("1e+", "t.json: invalid number (its exponent has no digits) at line 1, column 1");
    check_invalid("[0, 1e400]", "t.json: number too large for a double at line 1, column 5");
    check_invalid("-1.8e308", "t.json: number too large for a double at line 1, column 1");
    char digits[402];
    memset(digits, '9', 401);
    digits[401] = '\0';
    check_invalid(digits, "t.json: number too large for a double at line 1, column 1");
    /* cJSON's limit: 63 characters read, 64 refused. */
    char number[65] = "0.";
    memset(number + 2, '5', 62);
    number[63] = '\0';
    check_valid(number);
    number[63] = '5', number[64] = '\0';
    check_invalid_n(number, 64, json_limits_cjson,
                    "t.json: number of 64 characters (at most 63 are read) at line 1, column 1");
    CHECK(accepted(number, 64, json_limits_gltf));
}

static void test_strings(void)
{
    check_invalid("\"\x01\"", "t.json: control character (byte 0x01) in a JSON string at line 1, column 2");
    check_invalid("\"\\q\"", "t.json: invalid escape in a JSON string at line 1, column 2");
    check_invalid("\"\\u12G4\"", "t.json: invalid escape in a JSON string at line 1, column 2");
    check_invalid("[\"\\ud800\"]",
                  "t.json: unpaired UTF-16 surrogate (a \\u escape) in a JSON string at line 1, column 3");
    check_invalid("\"\\udc00\\ud800\"",
                  "t.json: unpaired UTF-16 surrogate (a \\u escape) in a JSON string at line 1, column 2");
    /* Ill-formed UTF-8 (Unicode table 3-7): overlong, surrogate, above
     * U+10FFFF, a stray continuation byte, a truncated sequence. */
    static const char *const bad[] = {"\"\xc0\x80\"", "\"\xe0\x80\x80\"", "\"\xed\xa0\x80\"", "\"\xf4\x90\x80\x80\"",
                                      "\"\x80\"", "\"\xe2\x82\"", "\"\xff\""};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i)
        check_invalid(bad[i], "t.json: invalid UTF-8 in a JSON string at line 1, column 2");
    /* Issue 21's example: the bad byte is character 631 of line 1 (the
     * two-byte e-acute before it is one character). */
    char text[700] = "{\"name\":\"\xc3\xa9";
    const size_t used = strlen(text); /* 11 bytes, 10 characters */
    memset(text + used, 'a', 620);
    memcpy(text + used + 620, "\xff\"}", 4);
    check_invalid(text, "t.json: invalid UTF-8 in a JSON string at line 1, column 631");
}

static void test_depth(void)
{
    char *deep = nested_arrays(JSON_MAX_DEPTH);
    check_valid(deep);
    free(deep);
    deep = nested_arrays(JSON_MAX_DEPTH + 1);
    check_invalid(deep, "t.json: JSON nests deeper than 256 arrays and objects at line 1, column 257");
    free(deep);
    /* Issue 21's first crash: 100,000 levels, refused before any parser. */
    deep = nested_arrays(100000);
    check_invalid(deep, "t.json: JSON nests deeper than 256 arrays and objects at line 1, column 257");
    free(deep);
    const json_limits shallow = {2, 0};
    check_invalid_n("{\"a\":{\"b\":[]}}", 14, shallow,
                    "t.json: JSON nests deeper than 2 arrays and objects at line 1, column 11");
}

int main(void)
{
    test_valid_texts();
    test_syntax_errors();
    test_numbers();
    test_strings();
    test_depth();
    return check_report("test_json_check");
}
