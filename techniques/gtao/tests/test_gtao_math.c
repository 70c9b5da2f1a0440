/* GTAO's mathematics against numerical integration and brute force, and the
 * transcription errors of the talk's code (seeds/001) shown to be errors. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "gtao/gtao.h"
#include "tests/check.h"

#define PI 3.14159265358979323846

static double arc_integrand(double theta, double n) { return cos(theta - n) * fabs(sin(theta)); }

/* Adaptive Simpson in double: the reference for IntegrateArc. */
static double simpson(double (*f)(double, double), double n, double a, double b, int intervals)
{
    double h = (b - a) / intervals, s = f(a, n) + f(b, n);
    for (int k = 1; k < intervals; ++k)
        s += (k & 1 ? 4 : 2) * f(a + k * h, n);
    return s * h / 3;
}

static uint32_t rng_state = 12345u;
static double uniform01(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return (rng_state >> 8) / 16777216.0;
}

/* IntegrateArc (cosine) equals the numerical integral of cos(theta - n)|sin theta|
 * over [h1, h2] for random normals and horizons inside the normal's hemisphere. */
static void test_integrate_arc_cosine(void)
{
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
        double n = (uniform01() - 0.5) * PI * 0.999;
        double h1 = (n - PI / 2) * uniform01(), h2 = (n + PI / 2) * uniform01();
        double numeric = simpson(arc_integrand, n, h1, 0, 2000) + simpson(arc_integrand, n, 0, h2, 2000);
        double analytic = gtao_integrate_arc_cosine((float)h1, (float)h2, (float)n);
        worst = fmax(worst, fabs(numeric - analytic));
    }
    printf("IntegrateArc cosine: max |analytic - numeric| = %.3g over 2000 random arcs\n", worst);
    CHECK(worst < 1e-6);
}

static double sin_abs(double theta, double n) { (void)n; return fabs(sin(theta)); }

static void test_integrate_arc_uniform(void)
{
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
        double h1 = -PI * uniform01(), h2 = PI * uniform01();
        double numeric = simpson(sin_abs, 0, h1, 0, 2000) + simpson(sin_abs, 0, 0, h2, 2000);
        worst = fmax(worst, fabs(numeric - gtao_integrate_arc_uniform((float)h1, (float)h2)));
    }
    CHECK(worst < 1e-6);
}

static double bent_v_integrand(double t, double n) { return cos(t) * cos(t - n) * fabs(sin(t)); }
static double bent_s_integrand(double t, double n) { return sin(t) * cos(t - n) * fabs(sin(t)); }

/* The closed-form bent-normal arc integrals equal Simpson's. */
static void test_integrate_arc_bent(void)
{
    double worst = 0;
    for (int i = 0; i < 1000; ++i) {
        double n = (uniform01() - 0.5) * PI * 0.999;
        double h1 = (n - PI / 2) * uniform01(), h2 = (n + PI / 2) * uniform01();
        float bv, bs;
        gtao_integrate_arc_bent((float)h1, (float)h2, (float)n, &bv, &bs);
        double v = simpson(bent_v_integrand, n, h1, 0, 2000) + simpson(bent_v_integrand, n, 0, h2, 2000);
        double s = simpson(bent_s_integrand, n, h1, 0, 2000) + simpson(bent_s_integrand, n, 0, h2, 2000);
        worst = fmax(worst, fmax(fabs(bv - v), fabs(bs - s)));
    }
    printf("bent arc integrals: max |closed form - numeric| = %.3g\n", worst);
    CHECK(worst < 1e-6);
}

/* Timonen's projection: with the arc weighted by |n_p|, the open hemisphere of
 * any normal integrates to exactly 1 over the slices (cosine AO of an open
 * hemisphere). The "Possible Pitfall" integrand |sin(theta - n)| does not. */
static double pitfall_integrand(double theta, double n) { return cos(theta - n) * fabs(sin(theta - n)); }

static void test_projected_normal_open_hemisphere(void)
{
    for (int i = 0; i < 20; ++i) {
        /* A unit normal facing the viewer (z towards the eye; v = +z in this frame). */
        double a = 2 * PI * uniform01(), c = 0.05 + 0.95 * uniform01(), s = sqrt(1 - c * c);
        double nx = s * cos(a), ny = s * sin(a), nz = c;
        double total = 0, pitfall = 0;
        const int slices = 720;
        for (int k = 0; k < slices; ++k) {
            double phi = PI * (k + 0.5) / slices;
            double along = nx * cos(phi) + ny * sin(phi); /* component along the slice's side vector */
            double len = sqrt(along * along + nz * nz), n = atan2(along, nz);
            total += len * gtao_integrate_arc_cosine((float)(n - PI / 2), (float)(n + PI / 2), (float)n);
            pitfall += len * (simpson(pitfall_integrand, n, n - PI / 2, 0, 400) +
                              simpson(pitfall_integrand, n, 0, n + PI / 2, 400));
        }
        CHECK_NEAR(total / slices, 1.0, 2e-6);
        if (c < 0.9)
            CHECK(fabs(pitfall / slices - 1.0) > 1e-2);
    }
}

/* "Method" writes h = -cos(max ...): the horizon angle is the arc cosine of
 * the largest cosine. A plane facing the viewer has horizon cosines 0. */
static void test_horizon_is_acos(void)
{
    CHECK_NEAR(gtao_integrate_arc_cosine(-acosf(0.0f), acosf(0.0f), 0.0f), 1.0, 1e-6);
    CHECK(fabs(gtao_integrate_arc_cosine(-cosf(0.0f), cosf(0.0f), 0.0f) - 1.0) > 0.1);
}

static double fast_sqrt_max_relative_error(uint32_t magic)
{
    double worst = 0;
    for (float x = 1.0f; x < 4.0f; x = nextafterf(x, 5.0f)) /* one period of the exponent */
        worst = fmax(worst, fabs(gtao_fast_sqrt_magic(x, magic) / sqrt(x) - 1));
    return worst;
}

/* The transcribed constant 0x1FB01DF5 is Drobot's 0x1FBD1DF5 with a digit lost:
 * measured over every float of a period, it is 2.3 times worse, and Drobot's
 * is close to the best constant a brute-force search finds. */
static void test_fast_sqrt(void)
{
    double drobot = fast_sqrt_max_relative_error(GTAO_FAST_SQRT_MAGIC);
    double transcribed = fast_sqrt_max_relative_error(GTAO_FAST_SQRT_MAGIC_AS_TRANSCRIBED);
    double best = 1;
    for (uint32_t m = 0x1FB00000u; m < 0x1FC00000u; m += 0x800u) {
        double w = 0;
        for (float x = 1.0f; x < 4.0f; x += 1.0f / 1024)
            w = fmax(w, fabs(gtao_fast_sqrt_magic(x, m) / sqrt(x) - 1));
        best = fmin(best, w);
    }
    printf("fast sqrt max relative error: Drobot 0x1FBD1DF5 %.4f, transcribed 0x1FB01DF5 %.4f, best constant %.4f\n",
           drobot, transcribed, best);
    CHECK(transcribed > 0.1);
    CHECK(drobot < 0.05);
    CHECK(drobot < best + 0.011);
}

/* GTAOFastCos is an arc cosine; its error is measured, with exact and fast sqrt. */
static void test_fast_acos(void)
{
    double worst = 0, worst_exact_sqrt = 0;
    for (int i = 0; i <= 200000; ++i) {
        float x = -1.0f + 2.0f * (float)i / 200000.0f;
        worst = fmax(worst, fabs(gtao_fast_acos(x) - acos(x)));
        float a = fabsf(x), r = (-0.156583f * a + (float)(PI / 2)) * sqrtf(1.0f - a);
        worst_exact_sqrt = fmax(worst_exact_sqrt, fabs((x >= 0 ? r : (float)PI - r) - acos(x)));
    }
    printf("fast acos max abs error: %.4f rad (%.4f with an exact sqrt)\n", worst, worst_exact_sqrt);
    CHECK(worst_exact_sqrt < 0.0095);
    CHECK(worst < 0.06);
    CHECK(fabs(gtao_fast_acos(0.5f) - acos(0.5)) < 0.06); /* not a cosine: cos(0.5) = 0.878 */
}

static int count_distinct(const float *v, int n, float period)
{
    int distinct = 0;
    for (int i = 0; i < n; ++i) {
        int seen = 0;
        for (int j = 0; j < i && !seen; ++j) {
            float d = fmodf(fabsf(v[i] - v[j]), period);
            seen = fminf(d, period - d) < 1e-4f;
        }
        distinct += !seen;
    }
    return distinct;
}

/* The 16 spatial directions of a 4x4 tile: every k/16 once, each row one in
 * every quarter turn ("each row contains a full rotation"). As transcribed,
 * the tile holds only 4 distinct directions. */
static void test_spatial_pattern(void)
{
    float fixed[16], transcribed[16], offsets[16];
    int hit[16] = {0};
    for (int y = 0; y < 4; ++y) {
        int quarters = 0;
        for (int x = 0; x < 4; ++x) {
            float u = gtao_spatial_direction(x + 8, y + 4); /* any tile */
            fixed[4 * y + x] = u;
            transcribed[4 * y + x] = gtao_spatial_direction_as_transcribed(x, y);
            offsets[4 * y + x] = gtao_spatial_offset(x, y);
            hit[(int)lroundf(16 * u) & 15]++;
            quarters |= 1 << (int)(4 * u);
        }
        CHECK(quarters == 15);
    }
    for (int k = 0; k < 16; ++k)
        CHECK(hit[k] == 1);
    CHECK(count_distinct(fixed, 16, 1.0f) == 16);
    CHECK(count_distinct(transcribed, 16, 1.0f) == 4);
    CHECK(count_distinct(offsets, 16, 1.0f) == 4);
    for (int y = 0; y < 4; ++y) /* 4 offsets in every row */
        CHECK(count_distinct(offsets + 4 * y, 4, 1.0f) == 4);
}

/* Spatial x temporal: 16 x 6 = 96 distinct slice directions and 4 x 4 = 16
 * distinct step offsets over a tile and the 24-frame cycle. Adding the
 * temporal values at full weight would give 48 and 4. */
static void test_temporal_pattern(void)
{
    float slices[16 * 24], offsets[16 * 24], slices_full[16 * 24], offsets_full[16 * 24];
    int n = 0;
    for (int f = 0; f < 24; ++f)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x, ++n) {
                slices[n] = gtao_slice_angle(x, y, f, 0, 1, 1);
                offsets[n] = gtao_step_offset(x, y, f, 1);
                slices_full[n] = gtao_spatial_direction(x, y) + gtao_temporal_rotation(f);
                offsets_full[n] = gtao_spatial_offset(x, y) + gtao_temporal_offset(f);
            }
    CHECK(count_distinct(slices, n, (float)PI) == 96);
    CHECK(count_distinct(offsets, n, 1.0f) == 16);
    CHECK(count_distinct(slices_full, n, 1.0f) == 48);
    CHECK(count_distinct(offsets_full, n, 1.0f) == 4);
    for (int i = 0; i < n; ++i)
        CHECK(slices[i] >= 0.0f && slices[i] < (float)PI && offsets[i] >= 0.0f && offsets[i] < 1.0f);
}

int main(void)
{
    test_integrate_arc_cosine();
    test_integrate_arc_uniform();
    test_integrate_arc_bent();
    test_projected_normal_open_hemisphere();
    test_horizon_is_acos();
    test_fast_sqrt();
    test_fast_acos();
    test_spatial_pattern();
    test_temporal_pattern();
    return check_report("test_gtao_math");
}
