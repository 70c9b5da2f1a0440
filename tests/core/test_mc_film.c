/* Monte Carlo film (core/statistics/mc_film.c) against a direct long-double computation
 * over the same samples: order- and split-independent exact sums, means and
 * standard errors, the even/odd half means, normalised vector layers, and an
 * exact round trip through an EXR file. Sample values are random floats, not
 * on the film's grid. */
#include <stdint.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "core/statistics/mc_film.h"
#include "tests/check.h"

#define W 5
#define H 3
#define PIXELS (W * H)
#define QUANTITIES 5
#define MAX_SAMPLES 80

static const mc_quantity quantities[QUANTITIES] = {
    {"ao.V", 0}, {"bent.X", 0}, {"bent.Y", 0}, {"bent.Z", 0}, {"big.V", 4}};

/* samples[p][i][q]: sample i (its sequence index) of pixel p. */
static float samples[PIXELS][MAX_SAMPLES][QUANTITIES];
static int sample_count[PIXELS];

static uint32_t rng_state = 0x2545f491u;
static uint32_t xorshift(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 17;
    rng_state ^= rng_state << 5;
    return rng_state;
}
static float uniform01(void) { return (float)(xorshift() >> 8) * 0x1p-24f; }

static void make_samples(void)
{
    for (int p = 0; p < PIXELS; ++p) {
        /* Counts differ per pixel, odd and even, one pixel with a single sample. */
        sample_count[p] = p == 7 ? 1 : 20 + 4 * p + p % 3;
        for (int i = 0; i < sample_count[p]; ++i) {
            /* Products of two random floats: full 24-bit mantissas, off the grid. */
            samples[p][i][0] = uniform01() * uniform01();
            samples[p][i][1] = 1.7f * uniform01() - 0.7f;
            samples[p][i][2] = (2.0f * uniform01() - 1.0f) * uniform01();
            samples[p][i][3] = uniform01() * 0.9f + 0.1f;
            samples[p][i][4] = 16.0f * uniform01() * uniform01();
        }
    }
}

static void init_film(mc_film *film)
{
    mc_film_init(film, W, H, quantities, QUANTITIES);
    mc_film_normalize_layer(film, "bent");
}

/* Adds the samples of each pixel whose index satisfies keep(i). */
static void add_in_order(mc_film *film, int reversed, int (*keep)(int))
{
    for (int p = 0; p < PIXELS; ++p)
        for (int k = 0; k < sample_count[p]; ++k) {
            int i = reversed ? sample_count[p] - 1 - k : k;
            if (!keep || keep(i))
                mc_film_add_sample(film, p, (uint32_t)i, samples[p][i]);
        }
}

static int first_part(int i) { return i % 3 == 0 || i < 5; }
static int second_part(int i) { return !first_part(i); }

static int same_accumulators(const mc_film *a, const mc_film *b)
{
    size_t n = (size_t)PIXELS * QUANTITIES;
    return memcmp(a->sum, b->sum, n * sizeof(int64_t)) == 0 &&
           memcmp(a->moments, b->moments, n * sizeof(moment_sums)) == 0 &&
           memcmp(a->sum_even, b->sum_even, n * sizeof(int64_t)) == 0 &&
           memcmp(a->count, b->count, PIXELS * sizeof(uint64_t)) == 0 &&
           memcmp(a->count_even, b->count_even, PIXELS * sizeof(uint64_t)) == 0;
}

/* Direct statistics of pixel p, quantity q over the samples with
 * half < 0: all, 0: even indices, 1: odd indices. */
typedef struct {
    long double mean, stderr_;
    int n;
} direct_stats;

static direct_stats direct(int p, int q, int half)
{
    long double sum = 0;
    int n = 0;
    for (int i = 0; i < sample_count[p]; ++i)
        if (half < 0 || i % 2 == half) {
            sum += samples[p][i][q];
            ++n;
        }
    direct_stats s = {n ? sum / n : 0, 0, n};
    long double ss = 0;
    for (int i = 0; i < sample_count[p]; ++i)
        if (half < 0 || i % 2 == half)
            ss += (samples[p][i][q] - s.mean) * (samples[p][i][q] - s.mean);
    s.stderr_ = n > 1 ? sqrtl(ss / (n - 1) / n) : INFINITY;
    return s;
}

/* (a) Different orders and a split-and-merge give the same bits. */
static void test_order_independence(void)
{
    mc_film forward, backward, part1, part2;
    init_film(&forward);
    init_film(&backward);
    init_film(&part1);
    init_film(&part2);
    add_in_order(&forward, 0, NULL);
    add_in_order(&backward, 1, NULL);
    add_in_order(&part1, 1, first_part);
    add_in_order(&part2, 0, second_part);
    gt_error e;
    CHECK(mc_film_merge(&part1, &part2, "part2", &e) == 0);
    CHECK_MSG(same_accumulators(&forward, &backward), "adding in reverse order changed the sums");
    CHECK_MSG(same_accumulators(&forward, &part1), "split and merge changed the sums");
    /* Merging the other way round too. */
    mc_film_free(&part2);
    init_film(&part2);
    add_in_order(&part2, 0, second_part);
    mc_film other;
    init_film(&other);
    add_in_order(&other, 0, first_part);
    CHECK(mc_film_merge(&part2, &other, "part1", &e) == 0);
    CHECK_MSG(same_accumulators(&forward, &part2), "merge in the other order changed the sums");

    /* Merging films of different shapes is refused. */
    mc_film small;
    mc_film_init(&small, 2, 2, quantities, QUANTITIES);
    CHECK(mc_film_merge(&forward, &small, "small.exr", &e) == -1 && strstr(e.message, "small.exr"));
    mc_film_free(&small);
    mc_film_init(&small, W, H, quantities, 2);
    CHECK(mc_film_merge(&forward, &small, "fewer.exr", &e) == -1 && strstr(e.message, "fewer.exr"));
    mc_film_free(&small);
    mc_film_free(&forward);
    mc_film_free(&backward);
    mc_film_free(&part1);
    mc_film_free(&part2);
    mc_film_free(&other);
}

/* (a') Adding runs of samples at once (quantity-major, any start parity and
 * length, vector body and scalar tail) gives the bits of adding them one by
 * one, the even count and even sums included. */
static void test_batches_equal_single_samples(void)
{
    mc_film one_by_one, batched;
    init_film(&one_by_one);
    init_film(&batched);
    add_in_order(&one_by_one, 0, NULL);
    for (int p = 0; p < PIXELS; ++p) {
        mc_pixel acc;
        mc_pixel_clear(&acc, &batched);
        for (int first = 0, run = 1; first < sample_count[p]; first += run, run = run % 13 + 2) {
            int count = first + run <= sample_count[p] ? run : sample_count[p] - first;
            float values[QUANTITIES * MAX_SAMPLES];
            for (int q = 0; q < QUANTITIES; ++q)
                for (int k = 0; k < count; ++k)
                    values[q * MAX_SAMPLES + k] = samples[p][first + k][q];
            mc_pixel_add_samples(&acc, &batched, (uint32_t)first, count, values, MAX_SAMPLES);
        }
        mc_film_add_pixel(&batched, p, &acc);
    }
    CHECK_MSG(same_accumulators(&one_by_one, &batched), "batched sums differ from single-sample sums");
    mc_film_free(&one_by_one);
    mc_film_free(&batched);
}

/* (b) Mean and standard error against the direct computation, to 1e-6 of
 * the pixel's statistical scale (the film rounds samples onto a grid of
 * 2^(E-24) for the means, far below the noise but not below every mean,
 * which may be near 0; the standard errors come from the moment sums,
 * tests/core/test_moment_sums.c). */
static void test_mean_and_stderr(void)
{
    mc_film film;
    init_film(&film);
    add_in_order(&film, 0, NULL);
    int bad_mean = 0, bad_err = 0;
    for (int p = 0; p < PIXELS; ++p)
        for (int q = 0; q < QUANTITIES; ++q) {
            direct_stats s = direct(p, q, -1);
            double mean = mc_film_mean(&film, q, p), err = mc_film_stderr(&film, q, p);
            if (sample_count[p] < 2) {
                CHECK(isinf(err));
                CHECK(mean == (double)samples[p][0][q] ||
                      fabs(mean - samples[p][0][q]) <= ldexp(1.0, quantities[q].scale_exponent - 25));
                continue;
            }
            double scale = fmax(fabs((double)s.mean), (double)s.stderr_);
            if (fabs(mean - (double)s.mean) > 1e-6 * scale && bad_mean++ < 5)
                fprintf(stderr, "pixel %d %s: mean %.12g, direct %.12Lg\n", p, quantities[q].name, mean, s.mean);
            if (fabs(err - (double)s.stderr_) > 1e-6 * (double)s.stderr_ && bad_err++ < 5)
                fprintf(stderr, "pixel %d %s: stderr %.12g, direct %.12Lg\n", p, quantities[q].name, err,
                        s.stderr_);
        }
    CHECK_MSG(bad_mean == 0, "%d means off", bad_mean);
    CHECK_MSG(bad_err == 0, "%d standard errors off", bad_err);
    CHECK(film.count[3] == (uint32_t)sample_count[3]);
    CHECK(film.count_even[3] == (uint32_t)(sample_count[3] + 1) / 2);
    mc_film_free(&film);
}

/* (c) Film -> channels -> EXR -> channels -> film is exact. */
static void test_exr_round_trip(void)
{
    mc_film film;
    init_film(&film);
    add_in_order(&film, 0, NULL);
    image written;
    image_init(&written, W, H);
    CHECK(mc_film_write_channels(&film, &written) == 0);
    char path[1200];
    snprintf(path, sizeof path, "%s/mc_film_round_trip.exr", check_tmp_dir());
    gt_error e;
    CHECK_MSG(exr_write(path, &written, &e) == 0, "%s", e.message);
    image read;
    if (exr_read(path, &read, &e) != 0) {
        CHECK_MSG(0, "%s", e.message);
        image_free(&written);
        mc_film_free(&film);
        return;
    }
    mc_film back;
    CHECK_MSG(mc_film_read_channels(&read, path, &back, &e) == 0, "%s", e.message);
    CHECK(back.width == W && back.height == H && back.quantity_count == QUANTITIES);
    size_t np = PIXELS;
    for (int q = 0; q < film.quantity_count; ++q) {
        int r = -1;
        for (int k = 0; k < back.quantity_count; ++k)
            if (strcmp(back.quantities[k].name, film.quantities[q].name) == 0)
                r = k;
        CHECK_MSG(r >= 0, "quantity %s lost", film.quantities[q].name);
        if (r < 0)
            continue;
        CHECK_MSG(memcmp(&film.sum[q * np], &back.sum[r * np], np * sizeof(int64_t)) == 0, "%s sums",
                  film.quantities[q].name);
        CHECK_MSG(memcmp(&film.moments[q * np], &back.moments[r * np], np * sizeof(moment_sums)) == 0,
                  "%s moment sums", film.quantities[q].name);
        CHECK_MSG(memcmp(&film.sum_even[q * np], &back.sum_even[r * np], np * sizeof(int64_t)) == 0, "%s even sums",
                  film.quantities[q].name);
    }
    CHECK(memcmp(film.count, back.count, np * sizeof(uint64_t)) == 0);
    CHECK(memcmp(film.count_even, back.count_even, np * sizeof(uint64_t)) == 0);
    CHECK(back.normalized_count == 1 && strcmp(back.normalized[0], "bent") == 0);

    /* Every channel the read-back film writes (means, normalised means,
     * standard errors, accumulators) has the bits of the original's. */
    image again;
    image_init(&again, W, H);
    CHECK(mc_film_write_channels(&back, &again) == 0);
    CHECK(again.channel_count == written.channel_count);
    for (int c = 0; c < written.channel_count; ++c) {
        const float *a = written.channels[c].data;
        const float *b = image_channel_data(&again, written.channels[c].name);
        const float *f = image_channel_data(&read, written.channels[c].name);
        CHECK_MSG(b && memcmp(a, b, np * sizeof(float)) == 0, "channel %s rewritten differs",
                  written.channels[c].name);
        CHECK_MSG(f && memcmp(a, f, np * sizeof(float)) == 0, "channel %s read from the EXR differs",
                  written.channels[c].name);
    }
    image_free(&again);
    mc_film_free(&back);
    image_free(&read);
    image_free(&written);
    mc_film_free(&film);
}

/* A render resumed from its file: read the film written after the first
 * samples, add the rest, and get the bits of the uninterrupted render. */
static int early(int i) { return i < 10; }
static int late(int i) { return i >= 10; }

static void test_resume_from_file(void)
{
    mc_film whole, first;
    init_film(&whole);
    add_in_order(&whole, 0, NULL);
    init_film(&first);
    add_in_order(&first, 0, early);
    image img;
    image_init(&img, W, H);
    mc_film_write_channels(&first, &img);
    mc_film resumed;
    gt_error e;
    if (mc_film_read_channels(&img, "partial.exr", &resumed, &e) != 0) {
        CHECK_MSG(0, "%s", e.message);
    } else {
        add_in_order(&resumed, 0, late);
        for (int q = 0; q < QUANTITIES; ++q)
            CHECK_MSG(resumed.quantities[q].scale_exponent == quantities[q].scale_exponent,
                      "quantity %s read back with scale exponent %d, written with %d", resumed.quantities[q].name,
                      resumed.quantities[q].scale_exponent, quantities[q].scale_exponent);
        CHECK_MSG(same_accumulators(&whole, &resumed), "resumed render differs from the uninterrupted one");
        mc_film_free(&resumed);
    }
    image_free(&img);
    mc_film_free(&first);
    mc_film_free(&whole);
}

/* Merging matches quantities by name: a film read from a checkpoint lists
 * them in the file's channel order, the render's film in the integrator's.
 * The samples added to a film of the quantities in reverse order, merged
 * into an empty film in the usual order, give the usual film's sums; a
 * film missing a quantity is refused, naming it. */
static void test_merge_matches_quantities_by_name(void)
{
    mc_quantity reversed_order[QUANTITIES];
    for (int q = 0; q < QUANTITIES; ++q)
        reversed_order[q] = quantities[QUANTITIES - 1 - q];
    mc_film whole, reversed, merged;
    init_film(&whole), init_film(&merged);
    add_in_order(&whole, 0, NULL);
    mc_film_init(&reversed, W, H, reversed_order, QUANTITIES);
    for (int p = 0; p < PIXELS; ++p)
        for (int i = 0; i < sample_count[p]; ++i) {
            float values[QUANTITIES];
            for (int q = 0; q < QUANTITIES; ++q)
                values[q] = samples[p][i][QUANTITIES - 1 - q];
            mc_film_add_sample(&reversed, p, (uint32_t)i, values);
        }
    gt_error e;
    CHECK_MSG(mc_film_merge(&merged, &reversed, "reversed", &e) == 0, "%s", e.message);
    CHECK_MSG(same_accumulators(&whole, &merged), "merged from the reversed quantity order: other sums");
    strcpy(reversed_order[0].name, "other.V");
    mc_film other;
    mc_film_init(&other, W, H, reversed_order, QUANTITIES);
    CHECK(mc_film_merge(&merged, &other, "other.exr", &e) != 0 &&
          strcmp(e.message, "other.exr: holds different quantities (no big.V)") == 0);
    mc_film_free(&other), mc_film_free(&reversed), mc_film_free(&merged), mc_film_free(&whole);
}

/* (d) Half means against the direct even / odd means; (e) the normalised
 * layer has unit vectors along the direct mean vector. */
static void test_half_means_and_normalised_layer(void)
{
    mc_film film;
    init_film(&film);
    add_in_order(&film, 0, NULL);
    for (int half = 0; half < 2; ++half) {
        image img;
        image_init(&img, W, H);
        CHECK(mc_film_write_half_means(&film, half, &img) == 0);
        const float *ao = image_channel_data(&img, "ao.V"), *big = image_channel_data(&img, "big.V");
        const float *b[3] = {image_channel_data(&img, "bent.X"), image_channel_data(&img, "bent.Y"),
                             image_channel_data(&img, "bent.Z")};
        for (int p = 0; p < PIXELS; ++p) {
            direct_stats s = direct(p, 0, half), t = direct(p, 4, half);
            if (s.n == 0) {
                CHECK(ao[p] == 0.0f && big[p] == 0.0f);
                continue;
            }
            CHECK_NEAR(ao[p], (double)s.mean, 1e-6 * fabs((double)s.mean) + 1e-7);
            CHECK_NEAR(big[p], (double)t.mean, 1e-6 * fabs((double)t.mean) + 16e-7);
            long double m[3], len = 0;
            for (int a = 0; a < 3; ++a) {
                m[a] = direct(p, 1 + a, half).mean;
                len += m[a] * m[a];
            }
            len = sqrtl(len);
            for (int a = 0; a < 3; ++a)
                CHECK_NEAR(b[a][p], (double)(m[a] / len), 1e-5);
        }
        image_free(&img);
    }

    image img;
    image_init(&img, W, H);
    CHECK(mc_film_write_channels(&film, &img) == 0);
    const char *layers = image_get_attribute(&img, "gtlab.normalized");
    CHECK(layers && strcmp(layers, "bent") == 0);
    const float *b[3] = {image_channel_data(&img, "bent.X"), image_channel_data(&img, "bent.Y"),
                         image_channel_data(&img, "bent.Z")};
    const float *ao = image_channel_data(&img, "ao.V");
    for (int p = 0; p < PIXELS; ++p) {
        double len = sqrt((double)b[0][p] * b[0][p] + (double)b[1][p] * b[1][p] + (double)b[2][p] * b[2][p]);
        CHECK_NEAR(len, 1.0, 1e-6);
        long double m[3], mlen = 0;
        for (int a = 0; a < 3; ++a) {
            m[a] = direct(p, 1 + a, -1).mean;
            mlen += m[a] * m[a];
        }
        mlen = sqrtl(mlen);
        for (int a = 0; a < 3; ++a)
            CHECK_NEAR(b[a][p], (double)(m[a] / mlen), 1e-5);
        /* Not a normalised layer: the plain mean. */
        CHECK_NEAR(ao[p], (double)direct(p, 0, -1).mean, 1e-6);
    }

    /* Pixels without a sample (a surface-only quantity's background) hold 0
     * in the means and standard errors; the others their mean. */
    mc_film sparse;
    CHECK(mc_film_init(&sparse, W, H, quantities, QUANTITIES) == 0);
    const float values[QUANTITIES] = {0.25f, 0.5f, 0.5f, 0.5f, 0.5f};
    for (int p = 0; p < PIXELS; p += 2)
        for (uint32_t k = 0; k < 4; ++k)
            mc_film_add_sample(&sparse, p, k, values);
    image masked;
    image_init(&masked, W, H);
    CHECK(mc_film_write_channels(&sparse, &masked) == 0);
    const float *mv = image_channel_data(&masked, "ao.V"), *ms = image_channel_data(&masked, "ao.V.stderr");
    for (int p = 0; p < PIXELS; ++p)
        CHECK(mv[p] == (p % 2 ? 0.0f : 0.25f) && ms[p] == 0.0f);
    image_free(&masked);
    mc_film_free(&sparse);
    image_free(&img);
    mc_film_free(&film);
}

/* (f) Images that are not reference renders are refused, naming the file. */
static void test_bad_images(void)
{
    gt_error e;
    mc_film film;
    image img;
    image_init(&img, W, H);
    image_add_channel(&img, "ao.V");
    image_add_channel(&img, "ao.V.stderr");
    CHECK(mc_film_read_channels(&img, "plain.exr", &film, &e) == -1);
    CHECK_MSG(strstr(e.message, "plain.exr") == e.message, "%s", e.message);

    image_add_channel(&img, "ao.V.sum"); /* an accumulator, but not all of them */
    image_add_channel(&img, "spp.N");
    image_add_channel(&img, "spp.Neven");
    CHECK(mc_film_read_channels(&img, "partial.exr", &film, &e) == -1);
    CHECK_MSG(strstr(e.message, "partial.exr") == e.message, "%s", e.message);
    image_free(&img);

    mc_film good;
    init_film(&good);
    add_in_order(&good, 0, NULL);
    image_init(&img, W, H);
    mc_film_write_channels(&good, &img);
    image_channel_data(&img, "spp.Neven")[4] = image_channel_data(&img, "spp.N")[4] + 1.0f;
    CHECK(mc_film_read_channels(&img, "counts.exr", &film, &e) == -1);
    CHECK_MSG(strstr(e.message, "counts.exr") == e.message, "%s", e.message);

    /* Sample counts a film cannot hold (not whole numbers, beyond 2^32,
     * infinite) are corrupt files too. */
    const float bad_counts[] = {2.5f, 1e10f, INFINITY};
    for (int k = 0; k < 3; ++k) {
        image_channel_data(&img, "spp.Neven")[4] = 0.0f;
        image_channel_data(&img, "spp.N")[4] = bad_counts[k];
        int rc = mc_film_read_channels(&img, "counts.exr", &film, &e);
        CHECK_MSG(rc == -1, "spp.N = %g accepted", (double)bad_counts[k]);
        if (rc == 0)
            mc_film_free(&film);
    }
    image_free(&img);
    mc_film_free(&good);
}

/* A copy of img without the moment-sum channels and with grid sums of
 * squares instead: the layout gtlab wrote before issue 23. */
static void make_legacy(const image *img, image *old)
{
    image_init(old, img->width, img->height);
    for (int c = 0; c < img->channel_count; ++c) {
        const char *name = img->channels[c].name, *dot = strrchr(name, '.');
        if (strcmp(dot, ".peak") == 0 || strncmp(dot, ".m1_", 4) == 0 || strncmp(dot, ".m2_", 4) == 0)
            continue;
        memcpy(image_add_channel(old, name), img->channels[c].data, sizeof(float) * PIXELS);
        if (strcmp(dot, ".sum") == 0) {
            char sq[128];
            snprintf(sq, sizeof sq, "%.*s.sumsq", (int)(dot - name), name);
            image_add_channel(old, sq);
        }
    }
    for (int a = 0; a < img->attribute_count; ++a)
        image_set_attribute(old, img->attributes[a].key, img->attributes[a].value);
}

/* (g) Files written before issue 23 still give their means and halves, but
 * have no standard errors to rebuild: merging them is refused, naming the
 * file. Corrupt moment channels are refused. */
static void test_legacy_and_corrupt_moments(void)
{
    mc_film film;
    init_film(&film);
    add_in_order(&film, 0, NULL);
    image img, old;
    image_init(&img, W, H);
    mc_film_write_channels(&film, &img);
    make_legacy(&img, &old);
    gt_error e;
    mc_film legacy;
    CHECK_MSG(mc_film_read_channels(&old, "old.exr", &legacy, &e) == 0, "%s", e.message);
    CHECK(legacy.has_moments == 0 && isnan(mc_film_stderr(&legacy, 0, 3)));
    CHECK(memcmp(legacy.sum, film.sum, sizeof(int64_t) * PIXELS * QUANTITIES) == 0);
    image half;
    image_init(&half, W, H);
    CHECK(mc_film_write_half_means(&legacy, 0, &half) == 0);
    CHECK_NEAR(image_channel_data(&half, "ao.V")[3], (double)direct(3, 0, 0).mean, 1e-6);
    image_free(&half);
    CHECK(mc_film_merge(&film, &legacy, "old.exr", &e) == -1 && strstr(e.message, "old.exr") == e.message);
    CHECK_MSG(strstr(e.message, "render it again") != NULL, "%s", e.message);
    CHECK(mc_film_merge(&legacy, &film, "new.exr", &e) == -1);
    mc_film_free(&legacy);
    image_free(&old);

    mc_film back;
    float *limb = image_channel_data(&img, "big.V.m2_1lo");
    float kept = limb[2];
    limb[2] += 0.5f;
    CHECK(mc_film_read_channels(&img, "limb.exr", &back, &e) == -1 && strstr(e.message, "limb.exr") == e.message);
    CHECK_MSG(strstr(e.message, "big.V.m2_1") != NULL, "%s", e.message);
    limb[2] = kept;
    image_channel_data(&img, "bent.Y.peak")[1] = -1.0f;
    CHECK(mc_film_read_channels(&img, "peak.exr", &back, &e) == -1 && strstr(e.message, "peak.exr") == e.message);
    image_free(&img);
    mc_film_free(&film);
}

/* (h) Sample counts as large as a film may hold stay exact in memory and
 * through files (issue 22): 2^24 and 2^24 - 1 samples merge into exactly
 * 2^25 - 1, written, read back and merged again; and a pixel doubled by
 * merging it with itself up to 2^32 samples keeps every sum exact (their
 * third float, "lo2", appears only then), its mean and half means exactly,
 * its standard error the closed form's; a merge past MC_FILM_MAX_COUNT
 * (2^32) is refused, naming the file, and leaves the film as it was. */
static void add_constant_samples(mc_film *film, uint32_t first, uint32_t count)
{
    enum { RUN = 4096 };
    static float values[RUN];
    for (int k = 0; k < RUN; ++k)
        values[k] = 0.5f + 0x1p-20f * (float)(k & 7);
    mc_pixel acc;
    mc_pixel_clear(&acc, film);
    for (uint32_t done = 0; done < count;) {
        int n = count - done < RUN ? (int)(count - done) : RUN;
        mc_pixel_add_samples(&acc, film, first + done, n, values, RUN);
        done += (uint32_t)n;
    }
    mc_film_add_pixel(film, 0, &acc);
}

/* film written and read back into *back; the image is kept in *img when
 * img is not NULL. */
static int through_file(const mc_film *film, mc_film *back, image *kept)
{
    image img;
    gt_error e;
    image_init(&img, film->width, film->height);
    int rc = mc_film_write_channels(film, &img) == 0 ? mc_film_read_channels(&img, "counts.exr", back, &e) : -1;
    if (rc != 0)
        fprintf(stderr, "through_file: %s\n", e.message);
    if (kept)
        *kept = img;
    else
        image_free(&img);
    return rc;
}

static void test_counts_beyond_2_24(void)
{
    static const mc_quantity one[1] = {{"v.V", 0}};
    mc_film a, b, a_back, b_back, merged_back, twice;
    gt_error e;
    mc_film_init(&a, 1, 1, one, 1);
    mc_film_init(&b, 1, 1, one, 1);
    add_constant_samples(&a, 0, 1u << 24);
    add_constant_samples(&b, 1u << 24, (1u << 24) - 1);
    CHECK(through_file(&a, &a_back, NULL) == 0 && through_file(&b, &b_back, NULL) == 0);
    CHECK(mc_film_merge(&a_back, &b_back, "b.exr", &e) == 0);
    CHECK(through_file(&a_back, &merged_back, NULL) == 0);
    CHECK_MSG(merged_back.count[0] == (1u << 25) - 1, "%.0f", (double)merged_back.count[0]);
    CHECK(merged_back.count_even[0] == 1u << 24);
    CHECK(mc_film_mean(&merged_back, 0, 0) == mc_film_mean(&a_back, 0, 0));
    CHECK(through_file(&merged_back, &twice, NULL) == 0);
    CHECK(mc_film_merge(&twice, &merged_back, "again.exr", &e) == 0 && twice.count[0] == (1u << 26) - 2);
    mc_film *films[6] = {&a, &b, &a_back, &b_back, &merged_back, &twice};
    for (int i = 0; i < 6; ++i)
        mc_film_free(films[i]);
}

static int has_channel(const image *img, const char *name) { return image_channel_data(img, name) != NULL; }

/* A film of the two samples, index 0 and 1. */
static void two_samples(mc_film *film, const float sample[2])
{
    static const mc_quantity one[1] = {{"v.V", 0}};
    mc_film_init(film, 1, 1, one, 1);
    mc_film_add_sample(film, 0, 0, &sample[0]);
    mc_film_add_sample(film, 0, 1, &sample[1]);
}

/* film += copy of itself through a file, `times` times: 2^times as many samples. */
static void double_through_files(mc_film *film, int times)
{
    gt_error e;
    for (int k = 0; k < times; ++k) {
        mc_film copy;
        CHECK(through_file(film, &copy, NULL) == 0 && mc_film_merge(film, &copy, "copy.exr", &e) == 0);
        mc_film_free(&copy);
    }
}

static void test_counts_to_2_32(void)
{
    const float sample[2] = {1.0f - 0x1p-22f, 0.3f};
    mc_film film, back;
    gt_error e;
    two_samples(&film, sample);
    double_through_files(&film, 31);
    CHECK(film.count[0] == 1ull << 32 && film.count_even[0] == 1ull << 31);
    CHECK(through_file(&film, &back, NULL) == 0 && back.count[0] == 1ull << 32);
    double mean = ((double)sample[0] + (double)sample[1]) / 2.0, n = 0x1p32, half = (sample[0] - sample[1]) / 2.0;
    CHECK_MSG(mc_film_mean(&back, 0, 0) == mean, "%.17g vs %.17g", mc_film_mean(&back, 0, 0), mean);
    double stderr_closed = sqrt(n / (n - 1.0) * half * half / n); /* s^2 = n/(n-1) ((a-b)/2)^2 */
    CHECK_NEAR(mc_film_stderr(&back, 0, 0), stderr_closed, 1e-9 * stderr_closed);
    image halves;
    image_init(&halves, 1, 1);
    CHECK(mc_film_write_half_means(&back, 0, &halves) == 0);
    float even_mean = (float)mc_grid_sum_value(mc_grid_units(sample[0], &film.grids[0]), &film.grids[0]);
    CHECK(image_channel_data(&halves, "v.V")[0] == even_mean);
    image_free(&halves);
    mc_film extra;
    two_samples(&extra, sample);
    CHECK(mc_film_merge(&back, &extra, "big.exr", &e) == -1);
    CHECK_MSG(strstr(e.message, "big.exr: ") == e.message && strstr(e.message, "2^32"), "%s", e.message);
    CHECK(back.count[0] == 1ull << 32); /* untouched */
    mc_film_free(&film), mc_film_free(&back), mc_film_free(&extra);
}

/* 0x55555555 copies of two samples (2863311530 samples): sums of about 54
 * significant bits, beyond hi + lo's 48 (and a double's 53 for the squares'
 * limbs), stay exact through a file in their third float, which ordinary
 * films do not carry. */
static void test_sums_beyond_48_bits(void)
{
    static const mc_quantity one[1] = {{"v.V", 0}};
    const float sample[2] = {1.0f - 0x1p-22f, 0.3f};
    const int64_t times = 0x55555555; /* alternate bits: no short hi + lo */
    mc_film power, total, back;
    gt_error e;
    two_samples(&power, sample);
    mc_film_init(&total, 1, 1, one, 1);
    image img;
    CHECK(through_file(&power, &back, &img) == 0 && !has_channel(&img, "v.V.sum_lo2"));
    image_free(&img), mc_film_free(&back);
    int64_t units = power.sum[0];
    for (int k = 0; k < 31; ++k) {
        if (times >> k & 1)
            CHECK(mc_film_merge(&total, &power, "power.exr", &e) == 0);
        double_through_files(&power, 1);
    }
    CHECK(total.count[0] == 2 * (uint64_t)times && total.sum[0] == units * times);
    CHECK(through_file(&total, &back, &img) == 0);
    CHECK(has_channel(&img, "v.V.sum_lo2") && has_channel(&img, "v.V.m1_1lo2"));
    CHECK(back.sum[0] == total.sum[0] && back.sum_even[0] == total.sum_even[0]);
    CHECK(memcmp(back.moments, total.moments, sizeof(moment_sums)) == 0);
    double mean = ((double)sample[0] + (double)sample[1]) / 2.0;
    CHECK_NEAR(mc_film_mean(&back, 0, 0), mean, 0x1p-48);
    image_free(&img);
    mc_film *films[3] = {&power, &total, &back};
    for (int i = 0; i < 3; ++i)
        mc_film_free(films[i]);
}

/* Rows taken back (an interrupted block of an adaptive render): emptying
 * row 1 of a full film and adding that row's samples again gives the full
 * film's accumulators exactly; the other rows are never touched. */
static int in_row_1(int pixel) { return pixel / W == 1; }

static void test_clear_rows(void)
{
    mc_film whole, film;
    init_film(&whole), init_film(&film);
    add_in_order(&whole, 0, NULL);
    add_in_order(&film, 0, NULL);
    mc_film_clear_rows(&film, 1, 2);
    for (int p = 0; p < PIXELS; ++p)
        CHECK(in_row_1(p) ? film.count[p] == 0 && film.sum[p] == 0 : film.count[p] == whole.count[p]);
    for (int p = 0; p < PIXELS; ++p)
        for (int k = 0; in_row_1(p) && k < sample_count[p]; ++k)
            mc_film_add_sample(&film, p, (uint32_t)k, samples[p][k]);
    CHECK_MSG(same_accumulators(&whole, &film), "a row emptied and rendered again differs");
    mc_film_free(&whole), mc_film_free(&film);
}

int main(void)
{
    make_samples();
    test_order_independence();
    test_batches_equal_single_samples();
    test_mean_and_stderr();
    test_exr_round_trip();
    test_resume_from_file();
    test_merge_matches_quantities_by_name();
    test_half_means_and_normalised_layer();
    test_bad_images();
    test_legacy_and_corrupt_moments();
    test_counts_beyond_2_24();
    test_counts_to_2_32();
    test_sums_beyond_48_bits();
    test_clear_rows();
    return check_report("test_mc_film");
}
