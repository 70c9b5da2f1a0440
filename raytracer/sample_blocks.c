/* Reading and writing the sample-block attribute (sample_blocks.h). */
#include "raytracer/sample_blocks.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/reference_schema.h"

/* The decimal number at *p, at most `max`, digits only; *p moves past it.
 * Returns 0, or -1 when there is no digit or the number exceeds max. */
static int read_decimal(const char **p, uint64_t max, uint64_t *out)
{
    const char *s = *p;
    uint64_t v = 0;
    if (*s < '0' || *s > '9')
        return -1;
    for (; *s >= '0' && *s <= '9'; ++s) {
        const uint64_t digit = (uint64_t)(*s - '0');
        if (v > (max - digit) / 10)
            return -1;
        v = 10 * v + digit;
    }
    *p = s;
    *out = v;
    return 0;
}

/* The block token at text (up to the next space), for a message. */
static const char *quote_token(const char *text, gt_quoted *q)
{
    char token[GT_QUOTE_MAX + 2];
    const size_t n = strcspn(text, " ");
    const size_t kept = n < sizeof token - 1 ? n : sizeof token - 1;
    memcpy(token, text, kept);
    token[kept] = '\0';
    return gt_quote(token, q);
}

/* Moves *p past the character c, or returns -1 when it is not there. */
static int expect_char(const char **p, char c)
{
    if (**p != c)
        return -1;
    ++*p;
    return 0;
}

/* One "seed:offset+count" at *p. Returns NULL, or what is wrong with it. */
static const char *read_block(const char **p, sample_block *b)
{
    uint64_t seed, offset, count;
    if (read_decimal(p, UINT64_MAX, &seed) != 0 || expect_char(p, ':') != 0 ||
        read_decimal(p, UINT64_MAX, &offset) != 0 || expect_char(p, '+') != 0 ||
        read_decimal(p, UINT64_MAX, &count) != 0 || (**p != ' ' && **p != '\0'))
        return "is not seed:offset+count (decimal numbers below 2^64)";
    if (seed > UINT32_MAX)
        return "has a seed above 2^32 - 1";
    if (count == 0)
        return "holds no samples";
    if (offset > SAMPLE_INDEX_LIMIT || count > SAMPLE_INDEX_LIMIT - offset)
        return "ends past sample 2^32 (sample indices are 32-bit)";
    b->seed = (uint32_t)seed;
    b->begin = offset;
    b->end = offset + count;
    return NULL;
}

int sample_blocks_parse(const char *text, const char *what, sample_block *blocks, int capacity, int *count,
                        gt_error *e)
{
    *count = 0;
    if (!text)
        return gt_error_set(e, what, "header attribute %s is missing (not a gtlab reference render?)", ATTR_BLOCKS);
    const char *p = text;
    for (;;) {
        while (*p == ' ')
            ++p;
        if (*p == '\0')
            break;
        if (*count == capacity)
            return gt_error_set(e, what, "header attribute %s: more than %d blocks", ATTR_BLOCKS, capacity);
        const char *start = p, *problem = read_block(&p, &blocks[*count]);
        gt_quoted q;
        if (problem)
            return gt_error_set(e, what, "header attribute %s: block %d ('%s') %s", ATTR_BLOCKS, *count + 1,
                                quote_token(start, &q), problem);
        ++*count;
    }
    return *count ? 0 : gt_error_set(e, what, "header attribute %s is empty", ATTR_BLOCKS);
}

char *sample_blocks_format(const sample_block *blocks, int count)
{
    /* "4294967295:4294967295+4294967296 ": at most 33 characters a block. */
    enum { per_block = 34 };
    const size_t size = (size_t)(count > 0 ? count : 0) * per_block + 1;
    char *text = malloc(size);
    if (!text)
        return NULL;
    size_t len = 0;
    text[0] = '\0';
    for (int i = 0; i < count && len < size; ++i)
        len += (size_t)snprintf(text + len, size - len, "%s%" PRIu32 ":%" PRIu64 "+%" PRIu64, i ? " " : "",
                                blocks[i].seed, blocks[i].begin, blocks[i].end - blocks[i].begin);
    return text;
}

static int block_order(const void *a, const void *b)
{
    const sample_block *x = a, *y = b;
    if (x->seed != y->seed)
        return x->seed < y->seed ? -1 : 1;
    return x->begin < y->begin ? -1 : x->begin > y->begin;
}

void sample_blocks_coalesce(sample_block *blocks, int *count)
{
    if (*count < 2)
        return;
    qsort(blocks, (size_t)*count, sizeof *blocks, block_order);
    int kept = 1;
    for (int i = 1; i < *count; ++i) {
        sample_block *last = &blocks[kept - 1];
        if (blocks[i].seed == last->seed && blocks[i].begin == last->end)
            last->end = blocks[i].end;
        else
            blocks[kept++] = blocks[i];
    }
    *count = kept;
}

int sample_blocks_within(const sample_block *b, const sample_block *plan, int n)
{
    for (int i = 0; i < n; ++i)
        if (plan[i].seed == b->seed && plan[i].begin <= b->begin && b->end <= plan[i].end)
            return 1;
    return 0;
}

/* The samples of one planned block that no block of `have` starts at, from
 * its beginning on: 1 with *gap, or 0 when they tile it. */
static int gap_in(const sample_block *have, int n_have, const sample_block *x, sample_block *gap)
{
    uint64_t at = x->begin;
    for (int i = 0; i < n_have && at < x->end; ++i)
        if (have[i].seed == x->seed && have[i].begin == at)
            at = have[i].end;
    if (at >= x->end)
        return 0;
    uint64_t next = x->end;
    for (int i = 0; i < n_have; ++i)
        if (have[i].seed == x->seed && have[i].begin > at && have[i].begin < next)
            next = have[i].begin;
    *gap = (sample_block){x->seed, at, next};
    return 1;
}

int sample_blocks_first_gap(const sample_block *have, int n_have, const sample_block *plan, int n_plan,
                            sample_block *gap)
{
    for (int i = 0; i < n_plan; ++i)
        if (gap_in(have, n_have, &plan[i], gap))
            return 1;
    return 0;
}
