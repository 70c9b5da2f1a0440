#include "raytracer/reference_merge.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/statistics/mc_film.h"
#include "raytracer/reference_quantity.h"
#include "raytracer/sample_blocks.h"
#include "core/reference_schema.h"

static int blocks_overlap(const sample_block *a, const sample_block *b)
{
    return a->seed == b->seed && a->begin < b->end && b->begin < a->end;
}

/* An adaptive render (--target-stderr, --target-rel-stderr) stops each
 * pixel when its own samples say so: parts stop at other points than one
 * render would, so their merge would equal no adaptive render. Refused. */
static int check_not_adaptive(const image *img, const char *name, gt_error *e)
{
    static const char *const keys[2] = {ATTR_TARGET_STDERR, ATTR_TARGET_REL_STDERR};
    for (int k = 0; k < 2; ++k) {
        double target;
        int found = schema_get_real(img, keys[k], name, &target, e);
        if (found < 0)
            return -1;
        if (found && target > 0.0)
            return gt_error_set(e, name,
                                "rendered with a stopping target (%s = %g): each pixel stopped by its own samples, so "
                                "merged parts would differ from one adaptive render; merge parts rendered without a "
                                "target (--spp only)",
                                keys[k], target);
    }
    return 0;
}

/* Plain samples V and corrected ones V - g + G estimate the same mean with
 * other variances: one render is one or the other. Absent means none (files
 * written before the control variate). */
static int check_same_control_variate(const image *first, const image *other, const char *name, gt_error *e)
{
    const char *a = image_get_attribute(first, ATTR_CONTROL_VARIATE);
    const char *b = image_get_attribute(other, ATTR_CONTROL_VARIATE);
    a = a ? a : "none";
    b = b ? b : "none";
    if (strcmp(a, b) != 0)
        return gt_error_set(e, name, "its %s is %s, the first input's %s: plain and control-variate samples do not "
                                     "merge into one render",
                            ATTR_CONTROL_VARIATE, b, a);
    return 0;
}

/* How two values of an attribute differ (issue 41: the user was not told):
 * both in full when short, else where they first differ. */
static void describe_difference(const char *first, const char *other, char *out, size_t size)
{
    if (!first || !other) {
        snprintf(out, size, "%s", first ? "it has none" : "the first has none");
        return;
    }
    if (strlen(first) <= 48 && strlen(other) <= 48) {
        snprintf(out, size, "'%s' against '%s'", other, first);
        return;
    }
    size_t at = 0;
    while (first[at] && first[at] == other[at])
        ++at;
    snprintf(out, size, "they first differ at character %zu: '%.24s' against '%.24s'", at + 1, other + at,
             first + at);
}

/* The attributes that must agree for a merge to make sense. */
static int check_compatible(const image *first, const image *other, const char *name, gt_error *e)
{
    /* The scene by its content hash: one file under two paths is one scene,
     * two files of one name are two. Files written before the hash was
     * recorded compare by their spec. */
    const int by_hash = image_get_attribute(first, ATTR_SCENE_HASH) || image_get_attribute(other, ATTR_SCENE_HASH);
    const char *const keys[] = {ATTR_QUANTITY, by_hash ? ATTR_SCENE_HASH : ATTR_SCENE, ATTR_CAMERA, ATTR_SETTINGS,
                                ATTR_NORMAL};
    if (image_get_attribute(other, ATTR_CHECKPOINT_OF)) /* issue 41: it was called a gtlab.quantity mismatch */
        return gt_error_set(e, name, "is the checkpoint of an unfinished render, not a part to merge: finish it "
                                     "with the same 'gtlab render' command and --resume, then merge its output");
    if (first->width != other->width || first->height != other->height)
        return gt_error_set(e, name, "size %dx%d differs from the first input's %dx%d", other->width, other->height,
                            first->width, first->height);
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; ++k) {
        const char *a = image_get_attribute(first, keys[k]), *b = image_get_attribute(other, keys[k]);
        if (!a || !b || strcmp(a, b) != 0) {
            char how[256];
            describe_difference(a, b, how, sizeof how);
            return gt_error_set(e, name, "its %s differs from the first input's (%s): not parts of one render",
                                keys[k], how);
        }
    }
    return check_same_control_variate(first, other, name, e);
}

/* Adds one block to the list, refusing it if it overlaps one there: those
 * samples would be counted twice. */
static int add_block(const sample_block *b, const char *name, sample_block *all, int *count, gt_error *e)
{
    for (int j = 0; j < *count; ++j)
        if (blocks_overlap(b, &all[j]))
            return gt_error_set(e, name,
                                "samples %" PRIu64 "..%" PRIu64 " of seed %" PRIu32
                                " are already in an earlier input: they would be counted twice",
                                b->begin, b->end - 1, b->seed);
    if (*count >= SAMPLE_BLOCKS_MAX)
        return gt_error_set(e, name, "too many sample blocks");
    all[(*count)++] = *b;
    return 0;
}

/* The blocks a planned merge must hold (coalesced); count 0: no plan. */
typedef struct {
    sample_block blocks[SAMPLE_BLOCKS_MAX];
    int count;
    const char *text;
} block_plan;

static int check_planned(const sample_block *b, const block_plan *plan, const char *name, gt_error *e)
{
    if (plan->count == 0 || sample_blocks_within(b, plan->blocks, plan->count))
        return 0;
    return gt_error_set(e, name,
                        "samples %" PRIu64 "..%" PRIu64 " of seed %" PRIu32
                        " are not in the planned blocks '%s': a part of another render",
                        b->begin, b->end - 1, b->seed, plan->text);
}

/* The merged blocks (coalesced) must be the whole plan. */
static int check_complete(const sample_block *have, int n, const block_plan *plan, gt_error *e)
{
    sample_block gap;
    if (plan->count == 0 || !sample_blocks_first_gap(have, n, plan->blocks, plan->count, &gap))
        return 0;
    return gt_error_set(e, "merge",
                        "no input holds samples %" PRIu64 "..%" PRIu64 " of seed %" PRIu32
                        " of the planned blocks '%s': a part is missing",
                        gap.begin, gap.end - 1, gap.seed, plan->text);
}

/* Adds the input's blocks (its header attribute, read by
 * raytracer/sample_blocks.h) to the list. */
static int add_blocks(const image *img, const char *name, const block_plan *plan, sample_block *all, int *count,
                      gt_error *e)
{
    sample_block *mine = malloc(sizeof *mine * SAMPLE_BLOCKS_MAX);
    int n = 0;
    if (!mine)
        return gt_error_set(e, name, "out of memory");
    int rc = sample_blocks_parse(image_get_attribute(img, ATTR_BLOCKS), name, mine, SAMPLE_BLOCKS_MAX, &n, e);
    for (int i = 0; rc == 0 && i < n; ++i)
        rc = check_planned(&mine[i], plan, name, e) != 0 ? -1 : add_block(&mine[i], name, all, count, e);
    free(mine);
    return rc;
}

/* Channels that the film writes and so must not be copied from the input. */
static int is_film_channel(const mc_film *film, const char *name)
{
    if (strncmp(name, "spp.", 4) == 0)
        return 1;
    for (int q = 0; q < film->quantity_count; ++q) {
        size_t n = strlen(film->quantities[q].name);
        if (strncmp(name, film->quantities[q].name, n) == 0 && (name[n] == '\0' || name[n] == '.'))
            return 1;
    }
    return 0;
}

static int write_merged(const reference_registry *quantities, const image *first, const mc_film *film,
                        const sample_block *blocks, int block_count, image *out)
{
    if (image_init(out, first->width, first->height) != 0)
        return -1;
    for (int c = 0; c < first->channel_count; ++c) {
        const image_channel *ch = &first->channels[c];
        if (is_film_channel(film, ch->name))
            continue;
        float *dst = image_add_channel(out, ch->name);
        if (!dst)
            return -1;
        memcpy(dst, ch->data, sizeof(float) * image_pixel_count(first));
    }
    if (mc_film_write_channels(film, out) != 0)
        return -1;
    /* Derived channels (ratios) from the merged sums: the quantity's finish. */
    const char *name = image_get_attribute(first, ATTR_QUANTITY);
    reference_quantity quantity = name ? reference_quantity_find(quantities, name) : NULL;
    if (quantity && quantity->finish && quantity->finish(out) != 0)
        return -1;
    for (int a = 0; a < first->attribute_count; ++a)
        if (image_set_attribute(out, first->attributes[a].key, first->attributes[a].value) != 0)
            return -1;
    /* At most 1024 blocks of at most 2^32 samples: the total fits. */
    uint64_t spp = 0;
    for (int i = 0; i < block_count; ++i)
        spp += blocks[i].end - blocks[i].begin;
    char spp_text[32];
    snprintf(spp_text, sizeof spp_text, "%" PRIu64, spp);
    char *text = sample_blocks_format(blocks, block_count);
    int rc = text ? image_set_attribute(out, ATTR_BLOCKS, text) | image_set_attribute(out, ATTR_SPP, spp_text) : -1;
    free(text);
    return rc;
}

/* Checks input i against the first and adds its blocks and sums to the total. */
static int merge_part(const image *inputs, const char *const *names, int i, const block_plan *plan, mc_film *total,
                      sample_block *blocks, int *block_count, gt_error *e)
{
    mc_film part;
    int rc = check_compatible(&inputs[0], &inputs[i], names[i], e);
    if (rc == 0)
        rc = check_not_adaptive(&inputs[i], names[i], e);
    if (rc == 0)
        rc = add_blocks(&inputs[i], names[i], plan, blocks, block_count, e);
    if (rc == 0 && (rc = mc_film_read_channels(&inputs[i], names[i], &part, e)) == 0) {
        rc = mc_film_merge(total, &part, names[i], e);
        mc_film_free(&part);
    }
    return rc;
}

/* The first input's film, then every other input merged into it. */
static int merge_all(const image *inputs, const char *const *names, int count, const block_plan *plan,
                     mc_film *total, sample_block *blocks, int *block_count, gt_error *e)
{
    if (mc_film_read_channels(&inputs[0], names[0], total, e) != 0)
        return -1;
    int rc = mc_film_check_moments(total, names[0], e);
    if (rc == 0)
        rc = check_not_adaptive(&inputs[0], names[0], e);
    if (rc == 0)
        rc = add_blocks(&inputs[0], names[0], plan, blocks, block_count, e);
    for (int i = 1; i < count && rc == 0; ++i)
        rc = merge_part(inputs, names, i, plan, total, blocks, block_count, e);
    if (rc == 0)
        sample_blocks_coalesce(blocks, block_count);
    if (rc == 0)
        rc = check_complete(blocks, *block_count, plan, e);
    if (rc != 0)
        mc_film_free(total);
    return rc;
}

static int read_plan(const char *planned, block_plan *plan, gt_error *e)
{
    plan->count = 0;
    plan->text = planned;
    if (!planned)
        return 0;
    if (sample_blocks_parse(planned, "--expect-blocks", plan->blocks, SAMPLE_BLOCKS_MAX, &plan->count, e) != 0)
        return -1;
    sample_blocks_coalesce(plan->blocks, &plan->count);
    return 0;
}

int reference_merge_planned(const reference_registry *quantities, const image *inputs, const char *const *names,
                            int count, const char *planned, image *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    if (count < 1)
        return gt_error_set(e, "merge", "no inputs");
    sample_block *blocks = malloc(sizeof *blocks * SAMPLE_BLOCKS_MAX);
    block_plan *plan = malloc(sizeof *plan);
    mc_film total;
    int block_count = 0, rc = blocks && plan ? 0 : gt_error_set(e, "merge", "out of memory");
    if (rc == 0)
        rc = read_plan(planned, plan, e);
    if (rc == 0)
        rc = merge_all(inputs, names, count, plan, &total, blocks, &block_count, e);
    if (rc == 0) {
        if (write_merged(quantities, &inputs[0], &total, blocks, block_count, out) != 0)
            rc = gt_error_set(e, "merge", "out of memory");
        mc_film_free(&total);
    }
    if (rc != 0)
        image_free(out);
    free(plan);
    free(blocks);
    return rc;
}

int reference_merge(const reference_registry *quantities, const image *inputs, const char *const *names, int count,
                    image *out, gt_error *e)
{
    return reference_merge_planned(quantities, inputs, names, count, NULL, out, e);
}
