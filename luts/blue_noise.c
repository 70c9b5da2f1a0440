/* Void-and-cluster blue noise (Ulichney 1993): see blue_noise.h. */
#include "luts/blue_noise.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "core/image.h"
#include "core/files/image_io.h"
#include "core/reference_schema.h"

#define BLUE_NOISE_RADIUS_MAX 9 /* exp(-81 / 4.5) = 1.5e-8 of the centre weight */

double blue_noise_uniform(uint64_t seed, uint64_t index)
{
    uint64_t z = seed * 0x9E3779B97F4A7C15ull + (index + 1) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1.0p-53;
}

uint64_t blue_noise_channel_seed(uint64_t seed, int channel) { return seed * 4 + (uint64_t)channel; }

/* The state of one array: pattern, energies, the toroidal Gaussian's taps. */
typedef struct {
    int n, radius;
    unsigned char *bit;
    double *energy;
    double weight[2 * BLUE_NOISE_RADIUS_MAX + 1][2 * BLUE_NOISE_RADIUS_MAX + 1];
} vac_state;

static void vac_weights(vac_state *s)
{
    for (int dy = -s->radius; dy <= s->radius; ++dy)
        for (int dx = -s->radius; dx <= s->radius; ++dx)
            s->weight[dy + s->radius][dx + s->radius] =
                exp(-(double)(dx * dx + dy * dy) / (2.0 * BLUE_NOISE_SIGMA * BLUE_NOISE_SIGMA));
}

/* Sets bit p to value and adds (or removes) its Gaussian to the energies. */
static void vac_set(vac_state *s, int p, int value)
{
    int n = s->n, px = p % n, py = p / n;
    double sign = value ? 1.0 : -1.0;
    s->bit[p] = (unsigned char)value;
    for (int dy = -s->radius; dy <= s->radius; ++dy) {
        int row = ((py + dy + n) % n) * n;
        for (int dx = -s->radius; dx <= s->radius; ++dx)
            s->energy[row + (px + dx + n) % n] += sign * s->weight[dy + s->radius][dx + s->radius];
    }
}

/* The tightest cluster (one of highest energy) or, for value 0, the largest
 * void (zero of lowest energy); the lowest index wins a tie. */
static int vac_find(const vac_state *s, int value)
{
    int best = -1, count = s->n * s->n;
    for (int p = 0; p < count; ++p) {
        if (s->bit[p] != value)
            continue;
        if (best < 0 || (value ? s->energy[p] > s->energy[best] : s->energy[p] < s->energy[best]))
            best = p;
    }
    return best;
}

/* Phase 0: m seeded random ones, then clusters moved to voids until stable. */
static int vac_initial_pattern(vac_state *s, uint64_t seed)
{
    int count = s->n * s->n, m = count / 10, placed = 0;
    for (uint64_t i = 0; placed < m; ++i) {
        int p = (int)(blue_noise_uniform(seed, i) * count);
        if (!s->bit[p]) {
            vac_set(s, p, 1);
            ++placed;
        }
    }
    for (int step = 0; step < 4 * count; ++step) { /* converges in far fewer */
        int cluster = vac_find(s, 1);
        vac_set(s, cluster, 0);
        int void_ = vac_find(s, 0);
        vac_set(s, void_, 1);
        if (void_ == cluster)
            break;
    }
    return m;
}

static void vac_copy(vac_state *dst, const vac_state *src)
{
    size_t count = (size_t)src->n * (size_t)src->n;
    memcpy(dst->bit, src->bit, count);
    memcpy(dst->energy, src->energy, count * sizeof(double));
}

/* Phases 1 and 2 from the initial pattern in s (scratch is overwritten). */
static void vac_rank(vac_state *s, vac_state *scratch, int m, uint32_t *rank)
{
    int count = s->n * s->n;
    vac_copy(scratch, s);
    for (int r = m - 1; r >= 0; --r) {
        int p = vac_find(scratch, 1);
        vac_set(scratch, p, 0);
        rank[p] = (uint32_t)r;
    }
    for (int r = m; r < count; ++r) {
        int p = vac_find(s, 0);
        vac_set(s, p, 1);
        rank[p] = (uint32_t)r;
    }
}

static int vac_alloc(vac_state *s, int n)
{
    size_t count = (size_t)n * (size_t)n;
    s->n = n;
    s->radius = (n - 1) / 2 < BLUE_NOISE_RADIUS_MAX ? (n - 1) / 2 : BLUE_NOISE_RADIUS_MAX;
    s->bit = calloc(count, 1);
    s->energy = calloc(count, sizeof(double));
    vac_weights(s);
    return s->bit && s->energy ? 0 : -1;
}

static void vac_free(vac_state *s)
{
    free(s->bit);
    free(s->energy);
}

int blue_noise_ranks(int size, uint64_t seed, uint32_t *rank, gt_error *e)
{
    if (size < 8 || size > 1024)
        return gt_error_set(e, "blue noise", "size %d outside [8, 1024]", size);
    vac_state *s = calloc(2, sizeof(vac_state));
    int rc = !s || vac_alloc(&s[0], size) != 0 || vac_alloc(&s[1], size) != 0;
    if (!rc)
        vac_rank(&s[0], &s[1], vac_initial_pattern(&s[0], seed), rank);
    if (s) {
        vac_free(&s[0]);
        vac_free(&s[1]);
    }
    free(s);
    return rc ? gt_error_set(e, "blue noise", "out of memory for %d^2", size) : 0;
}

int blue_noise_build(int size, int channel_count, uint64_t seed, blue_noise_texture *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    if (channel_count < 1 || channel_count > BLUE_NOISE_MAX_CHANNELS)
        return gt_error_set(e, "blue noise", "channel count %d outside [1, 4]", channel_count);
    size_t count = (size_t)size * (size_t)size;
    uint32_t *rank = malloc(count * sizeof *rank);
    out->values = malloc(count * (size_t)channel_count * sizeof(float));
    out->size = size;
    out->channel_count = channel_count;
    int rc = rank && out->values ? 0 : gt_error_set(e, "blue noise", "out of memory for %d^2", size);
    for (int c = 0; c < channel_count && rc == 0; ++c) {
        rc = blue_noise_ranks(size, blue_noise_channel_seed(seed, c), rank, e);
        for (size_t i = 0; i < count && rc == 0; ++i)
            out->values[(size_t)c * count + i] = (float)((rank[i] + 0.5) / (double)count);
    }
    free(rank);
    if (rc != 0)
        blue_noise_free(out);
    return rc;
}

void blue_noise_free(blue_noise_texture *t)
{
    free(t->values);
    t->values = NULL;
}

static int blue_noise_write_exr(const blue_noise_texture *t, const char *path, gt_error *e)
{
    static const char *const names[BLUE_NOISE_MAX_CHANNELS] = CH_BLUE_NOISE_RGBA;
    size_t count = (size_t)t->size * (size_t)t->size;
    image img;
    if (image_init(&img, t->size, t->size) != 0)
        return gt_error_set(e, path, "out of memory");
    int rc = 0;
    for (int c = 0; c < t->channel_count && rc == 0; ++c) {
        float *plane = image_add_channel(&img, names[c]);
        if (!plane)
            rc = gt_error_set(e, path, "out of memory");
        else
            memcpy(plane, t->values + (size_t)c * count, count * sizeof(float));
    }
    rc = rc == 0 ? exr_write(path, &img, e) : rc;
    image_free(&img);
    return rc;
}

int blue_noise_write(const blue_noise_texture *t, const char *stem, gt_error *e)
{
    char path[4096];
    size_t count = (size_t)t->size * (size_t)t->size;
    const float *planes[BLUE_NOISE_MAX_CHANNELS] = {NULL, NULL, NULL, NULL};
    for (int c = 0; c < t->channel_count; ++c)
        planes[c] = t->values + (size_t)c * count;
    if (snprintf(path, sizeof path, "%s.exr", stem) >= (int)sizeof path)
        return gt_error_set(e, stem, "path too long");
    if (blue_noise_write_exr(t, path, e) != 0)
        return -1;
    snprintf(path, sizeof path, "%s.png", stem);
    if (t->channel_count == 1)
        return image_write_data8(path, planes[0], t->size, t->size, "void-and-cluster blue noise", e);
    return image_write_data16(path, planes, t->channel_count, t->size, t->size, "void-and-cluster blue noise", e);
}

int blue_noise_make(const char *dir, int size, int channel_count, uint64_t seed, char *stem, size_t stem_size,
                    gt_error *e)
{
    blue_noise_texture t;
    if ((size_t)snprintf(stem, stem_size, "%s/blue_noise_%d", dir, size) >= stem_size)
        return gt_error_set(e, dir, "path too long");
    if (blue_noise_build(size, channel_count, seed, &t, e) != 0)
        return -1;
    int rc = blue_noise_write(&t, stem, e);
    blue_noise_free(&t);
    return rc;
}
