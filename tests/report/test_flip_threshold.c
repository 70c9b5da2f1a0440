/* CLAIM_FLIP_JUST_NOTICEABLE (report/claim_thresholds.h) is what gtlab's
 * FLIP gives the change it stands for: two uniform greys at L* 49.5 and
 * 50.5, one CIEDE2000 unit apart (CLAIM_VISIBLE_DE00, checked through
 * Little CMS, metrics/color_difference.h), scored by flip_grey, the figure
 * the studies report, at the default 67 pixels per degree. A uniform change
 * has no edge or point, and the contrast-sensitivity filters leave it
 * unchanged, so every pixel scores the colour term alone and the threshold
 * does not depend on the viewing distance (checked at 30 pixels per degree
 * too). One 8-bit sRGB code value at mid grey (127 -> 128), the smallest
 * change a back buffer shows there, scores below it. */
#include <math.h>
#include <stdlib.h>

#include "metrics/color_difference.h"
#include "metrics/flip.h"
#include "report/claim_thresholds.h"
#include "tests/check.h"

enum { W = 48, H = 40 };
#define N ((size_t)W * H)

/* Relative luminance of CIE lightness L* (above the linear segment). */
static double luminance_of_lightness(double l) { return pow((l + 16.0) / 116.0, 3.0); }

static double srgb_encode(double linear)
{
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
}

static double srgb_decode(double v) { return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4); }

/* Mean FLIP of a uniform grey `test` against a uniform grey `reference`
 * (linear values), through flip_grey, or LDR-FLIP at `ppd` when ppd > 0. */
static double uniform_flip(double reference, double test, double ppd)
{
    float *a = malloc(sizeof(float) * N), *b = malloc(sizeof(float) * N), *map = malloc(sizeof(float) * N);
    for (size_t i = 0; i < N; ++i)
        a[i] = (float)reference, b[i] = (float)test;
    gt_error e;
    double mean = NAN;
    if (ppd > 0.0) {
        flip_image r = {W, H, {a, a, a}}, t = {W, H, {b, b, b}};
        CHECK_MSG(flip_ldr(&r, &t, ppd, "uniform", map, &e) == 0, "%s", e.message);
        mean = flip_mean(map, NULL, N);
    } else {
        flip_result f;
        CHECK_MSG(flip_grey(a, b, NULL, W, H, "uniform", map, &f, &e) == 0, "%s", e.message);
        CHECK(!f.hdr);
        mean = f.mean;
    }
    free(a), free(b), free(map);
    return mean;
}

int main(void)
{
    double y0 = luminance_of_lightness(49.5), y1 = luminance_of_lightness(50.5);
    gt_error e;
    color_difference *cd = color_difference_create(&e);
    CHECK(cd != NULL);
    if (!cd)
        return check_report("report_flip_threshold");
    double s0 = srgb_encode(y0), s1 = srgb_encode(y1), a[3] = {s0, s0, s0}, b[3] = {s1, s1, s1}, de00;
    color_difference_ciede2000(cd, a, b, 1, &de00);
    color_difference_free(cd);
    printf("greys L* 49.5 and 50.5 (linear %.5f, %.5f): CIEDE2000 %.4f\n", y0, y1, de00);
    CHECK_NEAR(de00, CLAIM_VISIBLE_DE00, 0.01);

    double flip = uniform_flip(y0, y1, 0.0), reverse = uniform_flip(y1, y0, 0.0);
    double at30 = uniform_flip(y0, y1, 30.0);
    printf("mean FLIP of that change: %.5f (reversed %.5f, at 30 ppd %.5f); CLAIM_FLIP_JUST_NOTICEABLE %.5f\n", flip,
           reverse, at30, CLAIM_FLIP_JUST_NOTICEABLE);
    CHECK_NEAR(flip, CLAIM_FLIP_JUST_NOTICEABLE, 2e-4); /* the constant's last digit */
    CHECK_NEAR(reverse, flip, 1e-5);
    CHECK_NEAR(at30, flip, 1e-5);

    double code = uniform_flip(srgb_decode(127.0 / 255.0), srgb_decode(128.0 / 255.0), 0.0);
    printf("one sRGB code value at mid grey (127 -> 128): mean FLIP %.5f\n", code);
    CHECK(code > 0.0 && code < CLAIM_FLIP_JUST_NOTICEABLE);
    return check_report("report_flip_threshold");
}
