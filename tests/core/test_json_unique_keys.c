/* Repeated object names (core/files/json_unique_keys.h): refused with the
 * key and its path, in flat and nested objects and inside arrays; unique
 * names everywhere pass, however many; a repeated name in two different
 * objects is no repetition. */
#include "core/files/json_unique_keys.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tests/check.h"

/* The check's verdict on `text`: 0, or -1 with its message in e. */
static int check_text(const char *text, gt_error *e)
{
    cJSON *root = cJSON_Parse(text);
    CHECK_MSG(root != NULL, "not JSON: %s", text);
    int rc = root ? json_check_unique_keys(root, "f.json", e) : -1;
    cJSON_Delete(root);
    return rc;
}

static void refused(const char *text, const char *message)
{
    gt_error e = {{0}};
    CHECK_MSG(check_text(text, &e) == -1 && strcmp(e.message, message) == 0, "%s -> %s", text, e.message);
}

static void accepted(const char *text)
{
    gt_error e = {{0}};
    CHECK_MSG(check_text(text, &e) == 0, "%s -> %s", text, e.message);
}

static void test_repeated_names(void)
{
    refused("{\"spp\": 4, \"spp\": 64}", "f.json: duplicate key 'spp' at $ (a key may appear once in an object)");
    refused("{\"a\": 1, \"b\": 2, \"c\": {\"x\": 1}, \"a\": 3}",
            "f.json: duplicate key 'a' at $ (a key may appear once in an object)");
    refused("{\"scenes\": [{\"label\": \"a\"}, {\"path\": \"p\", \"label\": \"b\", \"label\": \"c\"}]}",
            "f.json: duplicate key 'label' at $.scenes[1] (a key may appear once in an object)");
    refused("[[1], [2, {\"k\": {\"z\": 0, \"z\": 1}}]]",
            "f.json: duplicate key 'z' at $[1][1].k (a key may appear once in an object)");
}

static void test_unique_names(void)
{
    accepted("{}");
    accepted("[]");
    accepted("3");
    accepted("{\"a\": {\"a\": {\"a\": 1}}, \"b\": [{\"a\": 1}, {\"a\": 2}]}");
    accepted("[{\"x\": []}, {}, [[[]]], {\"y\": {\"x\": 1}}]");
}

/* 20000 distinct keys pass and one repeated among them is found: the check
 * sorts, it does not compare every pair. */
static void test_many_keys(void)
{
    enum { KEYS = 20000 };
    char *text = malloc(KEYS * 16 + 32);
    size_t k = 0;
    text[k++] = '{';
    for (int i = 0; i < KEYS; ++i)
        k += (size_t)sprintf(text + k, "%s\"k%d\":%d", i ? "," : "", i, i);
    strcpy(text + k, "}");
    accepted(text);
    sprintf(text + k, ",\"k%d\":0}", KEYS / 2);
    refused(text, "f.json: duplicate key 'k10000' at $ (a key may appear once in an object)");
    free(text);
}

int main(void)
{
    test_repeated_names();
    test_unique_names();
    test_many_keys();
    return check_report("test_json_unique_keys");
}
