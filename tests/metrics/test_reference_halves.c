/* metrics/reference_halves.h on a synthetic film: each half holds the mean
 * of its own samples (even or odd indices) in every quantity, and 0 off the
 * mask; an image that is not a gtlab reference is an error. */
#include "core/statistics/mc_film.h"
#include "core/reference_schema.h"
#include "metrics/reference_halves.h"
#include "tests/check.h"

enum { W = 3, H = 2, PIXELS = W * H, SAMPLES = 6 };

/* Sample s of quantity q at pixel p: distinct values for even and odd s. */
static float value(int q, int p, int s)
{
    return 0.1f * (float)q + 0.01f * (float)p + (s % 2 ? 0.5f : 0.25f) * (float)(s + 1) / SAMPLES;
}

static double half_mean(int q, int p, int half)
{
    double sum = 0.0;
    for (int s = half; s < SAMPLES; s += 2)
        sum += value(q, p, s);
    return sum / (SAMPLES / 2);
}

/* A reference of two quantities, every pixel but the last on the mask. */
static void make_reference(image *img)
{
    static const mc_quantity quantities[2] = {{CH_AO, 0}, {"multibounce.V", 0}};
    mc_film film;
    CHECK(mc_film_init(&film, W, H, quantities, 2) == 0);
    for (int p = 0; p < PIXELS; ++p)
        for (int s = 0; s < SAMPLES; ++s) {
            const float values[2] = {value(0, p, s), value(1, p, s)};
            mc_film_add_sample(&film, p, (uint32_t)s, values);
        }
    float mask[PIXELS];
    for (int p = 0; p < PIXELS; ++p)
        mask[p] = p < PIXELS - 1 ? 1.0f : 0.0f;
    CHECK(image_init(img, W, H) == 0);
    float *plane = image_add_channel(img, CH_MASK);
    for (int p = 0; plane && p < PIXELS; ++p)
        plane[p] = mask[p];
    CHECK(mc_film_write_channels(&film, img) == 0);
    mc_film_free(&film);
}

static void test_halves_hold_their_samples_means(void)
{
    image img, halves[2];
    gt_error e;
    make_reference(&img);
    CHECK_MSG(reference_halves_split(&img, "synthetic", halves, &e) == 0, "%s", e.message);
    static const char *const names[2] = {CH_AO, "multibounce.V"};
    for (int h = 0; h < 2; ++h) {
        CHECK(halves[h].width == W && halves[h].height == H);
        for (int q = 0; q < 2; ++q) {
            const float *plane = image_channel_data(&halves[h], names[q]);
            CHECK(plane != NULL);
            for (int p = 0; plane && p < PIXELS; ++p)
                CHECK_NEAR(plane[p], p < PIXELS - 1 ? half_mean(q, p, h) : 0.0, 1e-6);
        }
        image_free(&halves[h]);
    }
    image_free(&img);
}

static void test_plain_image_is_an_error(void)
{
    image img, halves[2];
    gt_error e;
    CHECK(image_init(&img, W, H) == 0);
    CHECK(image_add_channel(&img, CH_AO) != NULL);
    CHECK(reference_halves_split(&img, "plain.exr", halves, &e) == -1);
    image_free(&img);
}

int main(void)
{
    test_halves_hold_their_samples_means();
    test_plain_image_is_an_error();
    return check_report("metrics_reference_halves");
}
