/* The sample-block header attribute (raytracer/sample_blocks.h) read as
 * hostile input: what gtlab writes reads back to the same blocks and the
 * same text; every number is overflow-checked (2^32 - 1 and 2^64 - 1 are
 * the edges, one more is refused); a block may reach sample 2^32 but not
 * pass it; at most 1024 blocks; a quoted block is cut to 80 characters. */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raytracer/sample_blocks.h"
#include "tests/check.h"

static sample_block blocks[SAMPLE_BLOCKS_MAX];

static int parse(const char *text, int *count, gt_error *e)
{
    return sample_blocks_parse(text, "f.exr", blocks, SAMPLE_BLOCKS_MAX, count, e);
}

static void check_refused(const char *text, const char *expected)
{
    int count;
    gt_error e = {{0}};
    CHECK_MSG(parse(text, &count, &e) == -1, "accepted '%.60s'", text);
    CHECK_MSG(strcmp(e.message, expected) == 0, "\n  got      '%s'\n  expected '%s'", e.message, expected);
}

static void test_round_trip(void)
{
    const char *text = "7:0+64 7:64+64 4294967295:4294967295+1 0:0+4294967296";
    int count;
    gt_error e;
    CHECK(parse(text, &count, &e) == 0 && count == 4);
    CHECK(blocks[0].seed == 7 && blocks[0].begin == 0 && blocks[0].end == 64);
    CHECK(blocks[2].seed == UINT32_MAX && blocks[2].begin == UINT32_MAX && blocks[2].end == ((uint64_t)1 << 32));
    CHECK(blocks[3].begin == 0 && blocks[3].end == ((uint64_t)1 << 32));
    char *written = sample_blocks_format(blocks, count);
    CHECK(written && strcmp(written, text) == 0);
    free(written);
    /* Extra spaces are read; the text written is canonical. */
    CHECK(parse("  1:2+3   4:5+6 ", &count, &e) == 0 && count == 2 && blocks[1].end == 11);
}

static void test_refused(void)
{
    int count;
    gt_error e;
    CHECK(parse(NULL, &count, &e) == -1 && strstr(e.message, "is missing"));
    check_refused("", "f.exr: header attribute gtlab.sample_blocks is empty");
    check_refused("1:2", "f.exr: header attribute gtlab.sample_blocks: block 1 ('1:2') is not seed:offset+count "
                         "(decimal numbers below 2^64)");
    check_refused("1:0+4 -1:0+4", "f.exr: header attribute gtlab.sample_blocks: block 2 ('-1:0+4') is not "
                                  "seed:offset+count (decimal numbers below 2^64)");
    check_refused("1:0+4x", "f.exr: header attribute gtlab.sample_blocks: block 1 ('1:0+4x') is not "
                            "seed:offset+count (decimal numbers below 2^64)");
    check_refused("1:0+18446744073709551616", "f.exr: header attribute gtlab.sample_blocks: block 1 "
                                              "('1:0+18446744073709551616') is not seed:offset+count (decimal "
                                              "numbers below 2^64)");
    check_refused("4294967296:0+1", "f.exr: header attribute gtlab.sample_blocks: block 1 ('4294967296:0+1') has "
                                    "a seed above 2^32 - 1");
    check_refused("1:5+0", "f.exr: header attribute gtlab.sample_blocks: block 1 ('1:5+0') holds no samples");
    check_refused("1:4294967295+2", "f.exr: header attribute gtlab.sample_blocks: block 1 ('1:4294967295+2') ends "
                                    "past sample 2^32 (sample indices are 32-bit)");
    /* Issue 21's crafted block: offset + count wraps around 2^64. */
    check_refused("4294967295:18446744073709551615+18446744073709551615",
                  "f.exr: header attribute gtlab.sample_blocks: block 1 "
                  "('4294967295:18446744073709551615+18446744073709551615') ends past sample 2^32 (sample indices "
                  "are 32-bit)");
}

static void test_bounds(void)
{
    /* 1024 blocks read; one more is refused. */
    char *text = malloc(16 * (SAMPLE_BLOCKS_MAX + 1));
    size_t len = 0;
    for (int i = 0; i <= SAMPLE_BLOCKS_MAX; ++i)
        len += (size_t)sprintf(text + len, "%s1:%d+1", i ? " " : "", i);
    int count;
    gt_error e;
    CHECK(parse(text, &count, &e) == -1 && strstr(e.message, "more than 1024 blocks"));
    text[strlen(text) - strlen(" 1:1024+1")] = '\0';
    CHECK(parse(text, &count, &e) == 0 && count == SAMPLE_BLOCKS_MAX);
    char *written = sample_blocks_format(blocks, count);
    CHECK(written && strcmp(written, text) == 0);
    free(written);
    free(text);
    /* A 5,000-digit block: no overflow, quoted cut to 80 characters. */
    char *digits = malloc(5001);
    memset(digits, '9', 5000);
    digits[5000] = '\0';
    CHECK(parse(digits, &count, &e) == -1);
    const char *quote = strstr(e.message, "('");
    CHECK(quote && strspn(quote + 2, "9") == 80 && strncmp(quote + 82, "...')", 5) == 0);
    free(digits);
}

/* Coalescing sorts and joins touching blocks of one seed (the text of a
 * merge of parts is the text of the whole); within and first_gap answer the
 * plan checks of gtlab merge --expect-blocks. */
static void test_coalesce_and_plan(void)
{
    int count;
    gt_error e;
    CHECK(parse("2:8+8 1:16+16 2:0+4 1:0+16 1:40+8", &count, &e) == 0 && count == 5);
    sample_blocks_coalesce(blocks, &count);
    char *text = sample_blocks_format(blocks, count);
    CHECK_MSG(text && strcmp(text, "1:0+32 1:40+8 2:0+4 2:8+8") == 0, "coalesced to '%s'", text);
    free(text);
    sample_block plan[2] = {{1, 0, 48}, {2, 0, 16}};
    sample_block inside = {1, 40, 48}, other_seed = {3, 0, 4}, past = {2, 12, 17};
    CHECK(sample_blocks_within(&inside, plan, 2) && !sample_blocks_within(&other_seed, plan, 2) &&
          !sample_blocks_within(&past, plan, 2));
    sample_block gap;
    CHECK(sample_blocks_first_gap(blocks, count, plan, 2, &gap) == 1);
    CHECK_MSG(gap.seed == 1 && gap.begin == 32 && gap.end == 40, "gap %" PRIu32 ":%" PRIu64 "..%" PRIu64, gap.seed,
              gap.begin, gap.end);
    sample_block whole[2] = {{1, 0, 48}, {2, 0, 16}};
    CHECK(sample_blocks_first_gap(whole, 2, plan, 2, &gap) == 0);
    sample_block tail_missing[2] = {{1, 0, 48}, {2, 0, 8}};
    CHECK(sample_blocks_first_gap(tail_missing, 2, plan, 2, &gap) == 1 && gap.seed == 2 && gap.begin == 8 &&
          gap.end == 16);
}

int main(void)
{
    test_round_trip();
    test_refused();
    test_bounds();
    test_coalesce_and_plan();
    return check_report("test_sample_blocks");
}
