/* The noise floor of a reference: SSIM between the means of its even- and
 * odd-index samples, read back from the accumulator channels of a render. A
 * film whose even samples are all a and odd samples all b has halves that are
 * the constant images a and b, whose SSIM has a closed form. */
#include <string.h>

#include "core/statistics/mc_film.h"
#include "metrics/ssim.h"
#include "tests/check.h"

enum { W = 16, H = 14 };
static const double C1 = 0.01 * 0.01;

/* A written reference with quantities ao.V and ao.Vuniform; pixel p gets
 * samples_per_pixel samples alternating even_value, odd_value for ao.V
 * (ao.Vuniform: 0.5). Pixels with outside[p] set get `outside_value`
 * alternating in sign instead. */
static void make_reference(image *img, int samples_per_pixel, float even_value, float odd_value,
                           const float *outside, float outside_value)
{
    const mc_quantity quantities[2] = {{"ao.V", 11 /* room for outside_value */}, {"ao.Vuniform", 0}};
    mc_film film;
    CHECK(mc_film_init(&film, W, H, quantities, 2) == 0);
    for (int p = 0; p < W * H; ++p)
        for (int s = 0; s < samples_per_pixel; ++s) {
            int even = s % 2 == 0;
            float v[2] = {even ? even_value : odd_value, 0.5f};
            if (outside && outside[p] == 0.0f)
                v[0] = even ? outside_value : -outside_value;
            mc_film_add_sample(&film, p, (uint32_t)s, v);
        }
    CHECK(image_init(img, W, H) == 0);
    CHECK(mc_film_write_channels(&film, img) == 0);
    mc_film_free(&film);
}

static void test_constant_halves(void)
{
    image ref;
    make_reference(&ref, 6, 0.25f, 0.75f, NULL, 0.0f);
    ssim_result r;
    gt_error e;
    CHECK(ssim_noise_floor(&ref, "ref.exr", "ao.V", NULL, &r, &e) == 0);
    double expected = (2 * 0.25 * 0.75 + C1) / (0.25 * 0.25 + 0.75 * 0.75 + C1);
    CHECK_NEAR(r.ssim, expected, 1e-12);
    CHECK_NEAR(r.dssim, (1 - expected) / 2, 1e-12);
    CHECK(r.centres == (size_t)(W - 10) * (H - 10));
    /* ao.Vuniform has equal halves: a noise floor of exactly 0. */
    CHECK(ssim_noise_floor(&ref, "ref.exr", "ao.Vuniform", NULL, &r, &e) == 0);
    CHECK(r.dssim == 0.0);
    image_free(&ref);
}

/* Outside the mask the halves are set to 0, as the written mean is: wild
 * samples there must not matter. Expected: SSIM of planes built by hand. */
static void test_mask(void)
{
    float mask[W * H], even[W * H], odd[W * H];
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            int inside = x + y < 20;
            mask[y * W + x] = inside ? 1.0f : 0.0f;
            even[y * W + x] = inside ? 0.25f : 0.0f;
            odd[y * W + x] = inside ? 0.75f : 0.0f;
        }
    image ref;
    make_reference(&ref, 4, 0.25f, 0.75f, mask, 1000.0f);
    ssim_result r, expected;
    gt_error e;
    CHECK(ssim_noise_floor(&ref, "ref.exr", "ao.V", mask, &r, &e) == 0);
    CHECK(ssim_compute(even, odd, mask, W, H, "t", NULL, &expected, &e) == 0);
    CHECK(r.ssim == expected.ssim);
    CHECK(r.centres == expected.centres);
    image_free(&ref);
}

static void test_errors(void)
{
    gt_error e;
    ssim_result r;
    image ref;
    make_reference(&ref, 4, 0.25f, 0.75f, NULL, 0.0f);
    CHECK(ssim_noise_floor(&ref, "ref.exr", "bent.X", NULL, &r, &e) == -1);
    CHECK(strcmp(e.message, "ref.exr: channel bent.X is not one of this reference's Monte Carlo quantities") == 0);
    image_free(&ref);

    make_reference(&ref, 1, 0.25f, 0.75f, NULL, 0.0f); /* one sample: the odd half is empty */
    CHECK(ssim_noise_floor(&ref, "ref.exr", "ao.V", NULL, &r, &e) == -1);
    CHECK(strstr(e.message, "ref.exr: pixel (0, 0) has 1 sample(s)") == e.message);
    image_free(&ref);

    image plain;
    CHECK(image_init(&plain, W, H) == 0);
    CHECK(image_add_channel(&plain, "ao.V") != NULL);
    CHECK(ssim_noise_floor(&plain, "approx.exr", "ao.V", NULL, &r, &e) == -1);
    CHECK(strstr(e.message, "approx.exr: ") == e.message && strstr(e.message, "not a gtlab reference"));
    image_free(&plain);
}

int main(void)
{
    test_constant_halves();
    test_mask();
    test_errors();
    return check_report("metrics_noise_floor");
}
