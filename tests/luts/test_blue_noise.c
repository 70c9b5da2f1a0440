/* Void-and-cluster blue noise (luts/blue_noise.c) and the radially averaged
 * power spectrum (metrics/dither_metrics.c):
 *  - the spectrum's normalisation: white noise of variance 1/12 (uniform)
 *    has a flat spectrum at 1/12 (averaged over 16 textures: rings 4 .. 32
 *    within 25 %, about 5 standard errors; all rings' mean within 5 %);
 *  - blue noise, 64^2: every rank once (a flat histogram: value (r + 1/2) /
 *    n^2, the ranks on which techniques/dither/tests/test_dither.c checks
 *    the triangular remap's CDF); low energy below
 *    the cut-off (rings 1 .. 6 below 1/10 of white) and more than white at
 *    the top (rings 20 .. 32);
 *  - the periodogram's peak ratio: a cosine of frequency (3, 0) puts all
 *    the power into two bins, (N^2 - 1) / 2 exactly; white noise's largest
 *    of ~N^2 / 2 exponential values is near ln(N^2 / 2) + 0.58 ~ 8.2 (held
 *    within [4, 20]); blue noise stays within that too (no structure);
 *  - deterministic: the same seed gives the same bits, another seed other
 *    bits; channel c of a 4-channel texture holds the ranks of
 *    blue_noise_channel_seed(seed, c);
 *  - bad sizes and channel counts refused. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/vec3.h" /* M_PI */
#include "luts/blue_noise.h"
#include "metrics/dither_metrics.h"
#include "tests/check.h"

#define N 64
#define WHITE_TEXTURES 16

static double ring_mean(const double *p, int lo, int hi)
{
    double s = 0;
    for (int k = lo; k <= hi; ++k)
        s += p[k];
    return s / (hi - lo + 1);
}

static void check_white_spectrum(void)
{
    static double v[N * N];
    double p[N / 2 + 1] = {0}, one[N / 2 + 1];
    for (int t = 0; t < WHITE_TEXTURES; ++t) {
        for (int i = 0; i < N * N; ++i)
            v[i] = blue_noise_uniform(3 + t, i);
        CHECK(dither_radial_power_spectrum(v, N, one, NULL) == 0);
        for (int k = 0; k <= N / 2; ++k)
            p[k] += one[k] / WHITE_TEXTURES;
    }
    for (int k = 4; k <= N / 2; ++k) /* ring k: ~2 pi k 16 exponential values: SE < 5 % */
        CHECK_MSG(fabs(p[k] - 1.0 / 12) < 0.25 / 12, "white ring %d: %g", k, p[k]);
    CHECK_NEAR(ring_mean(p, 1, N / 2), 1.0 / 12, 0.05 / 12);
}

static void check_blue_noise(const blue_noise_texture *t)
{
    static double v[N * N];
    static int seen[N * N];
    double p[N / 2 + 1];
    memset(seen, 0, sizeof seen);
    for (int i = 0; i < N * N; ++i) {
        v[i] = t->values[i];
        int r = (int)(t->values[i] * N * N);
        CHECK(r >= 0 && r < N * N && fabs(t->values[i] - (r + 0.5) / (N * N)) < 1e-6);
        seen[r < 0 || r >= N * N ? 0 : r]++;
    }
    int missing = 0;
    for (int r = 0; r < N * N; ++r)
        missing += seen[r] != 1;
    CHECK_MSG(missing == 0, "%d ranks not seen once", missing);
    CHECK(dither_radial_power_spectrum(v, N, p, NULL) == 0);
    CHECK_MSG(ring_mean(p, 1, 6) < 0.1 / 12, "low rings %g", ring_mean(p, 1, 6));
    CHECK_MSG(ring_mean(p, 20, 32) > 1.0 / 12, "high rings %g", ring_mean(p, 20, 32));
}

static void check_determinism(const blue_noise_texture *t)
{
    blue_noise_texture again, other, four;
    gt_error e;
    CHECK(blue_noise_build(N, 1, 11, &again, &e) == 0 && blue_noise_build(N, 1, 12, &other, &e) == 0);
    CHECK(memcmp(again.values, t->values, sizeof(float) * N * N) == 0);
    CHECK(memcmp(other.values, t->values, sizeof(float) * N * N) != 0);
    CHECK(blue_noise_build(N, 4, 5, &four, &e) == 0);
    static uint32_t rank[N * N];
    for (int c = 0; c < 4; ++c) {
        CHECK(blue_noise_ranks(N, blue_noise_channel_seed(5, c), rank, &e) == 0);
        int differ = 0;
        for (int i = 0; i < N * N; ++i)
            differ += four.values[(size_t)c * N * N + i] != (float)((rank[i] + 0.5) / (N * N));
        CHECK(differ == 0);
    }
    blue_noise_free(&again), blue_noise_free(&other), blue_noise_free(&four);
}

static void check_spectrum_peak(const blue_noise_texture *t)
{
    static double v[N * N];
    double ratio = 0.0;
    for (int i = 0; i < N * N; ++i)
        v[i] = cos(2.0 * M_PI * 3.0 * (i % N) / N);
    CHECK(dither_spectrum_peak_ratio(v, N, &ratio, NULL) == 0);
    CHECK_NEAR(ratio, (N * N - 1) / 2.0, 1e-6 * N * N);
    for (int i = 0; i < N * N; ++i)
        v[i] = blue_noise_uniform(7, i);
    CHECK(dither_spectrum_peak_ratio(v, N, &ratio, NULL) == 0);
    CHECK_MSG(ratio > 4.0 && ratio < 20.0, "white noise peak ratio %g", ratio);
    for (int i = 0; i < N * N; ++i)
        v[i] = t->values[i];
    CHECK(dither_spectrum_peak_ratio(v, N, &ratio, NULL) == 0);
    CHECK_MSG(ratio < 20.0, "blue noise peak ratio %g", ratio);
    CHECK(dither_spectrum_peak_ratio(v, 1, &ratio, NULL) != 0);
}

int main(void)
{
    blue_noise_texture t, bad;
    gt_error e;
    check_white_spectrum();
    CHECK(blue_noise_build(N, 1, 11, &t, &e) == 0);
    check_blue_noise(&t);
    check_determinism(&t);
    check_spectrum_peak(&t);
    CHECK(blue_noise_build(4, 1, 1, &bad, &e) != 0 && blue_noise_build(N, 5, 1, &bad, &e) != 0);
    blue_noise_free(&t);
    return check_report("test_blue_noise");
}
