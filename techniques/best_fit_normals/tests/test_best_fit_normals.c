/* Best-fit normals (best_fit_normals/best_fit_normals.h) against what they must be:
 * - every table value is t = k / 255 with k odd in 3..255, so 8 bits hold it;
 * - the talk's search and the angle search never beat the exhaustive best
 *   cell, and the angle search is never worse than the talk's metric (same
 *   probes); the exhaustive 3 x 3 neighbourhood finds the same angle as a
 *   brute force over all 256^3 cells for random directions;
 * - the table's point lookup at a texel centre returns that texel, and the
 *   lookup is the same for the 48 symmetric images of a direction;
 * - the table's bits do not depend on the thread count;
 * - cell counts: the surface count is 256^3 - 254^3; the distinct-direction
 *   count equals the Moebius sum over odd d of mu(d) (odd multiples of d in
 *   -255..255)^3; sampled counts grow with the face size and stay below the
 *   exact counts they approach; counting 1/48 of the cubemap with the 48
 *   symmetric images of each cell equals counting every texel. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "best_fit_normals/best_fit_normals.h"
#include "best_fit_normals/best_fit_normals_cells.h"
#include "best_fit_normals/best_fit_normals_writers.h"
#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "core/vec3.h" /* M_PI */
#include "tests/check.h"

static double uniform(unsigned long long *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) * 0x1.0p-53;
}

static void random_direction(unsigned long long *s, double n[3])
{
    double z = 2.0 * uniform(s) - 1.0, phi = 2.0 * M_PI * uniform(s), r = sqrt(1.0 - z * z);
    n[0] = r * cos(phi);
    n[1] = r * sin(phi);
    n[2] = z;
}

static double brute_force_best_angle(const double n[3])
{
    double best = INFINITY;
    for (int a = 0; a < 256; ++a)
        for (int b = 0; b < 256; ++b)
            for (int c = 0; c < 256; ++c) {
                double q[3] = {bfn_code_value(a), bfn_code_value(b), bfn_code_value(c)};
                best = fmin(best, bfn_angle(q, n));
            }
    return best;
}

static void check_searches(void)
{
    unsigned long long s = 7;
    for (int k = 0; k < 2000; ++k) {
        double n[3], qp[3], qa[3], qe[3];
        random_direction(&s, n);
        bfn_best_scale(n, BFN_ERROR_PUBLISHED, qp);
        bfn_best_scale(n, BFN_ERROR_ANGLE, qa);
        double ep = bfn_angle(qp, n), ea = bfn_angle(qa, n), ee = bfn_best_cell_exhaustive(n, qe);
        CHECK_MSG(ee <= ea + 1e-15 && ea <= ep + 1e-15, "exhaustive %g angle %g published %g", ee, ea, ep);
        if (k < 3)
            CHECK_NEAR(ee, brute_force_best_angle(n), 1e-15);
    }
}

/* t is the float of k / 255 for an odd k in 3..255: an 8-bit texel holds it. */
static int odd_k_in_range(float t)
{
    long k = lround(t * 255.0);
    return (float)(k / 255.0) == t && k % 2 == 1 && k >= 3 && k <= 255;
}

static void check_table(void)
{
    enum { N = 64 };
    float *t1 = bfn_table_build(N, BFN_ERROR_PUBLISHED, 1), *t2 = bfn_table_build(N, BFN_ERROR_PUBLISHED, 2);
    CHECK(t1 && t2 && memcmp(t1, t2, sizeof(float) * N * N) == 0);
    int exact = 1, centres = 1;
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            exact &= odd_k_in_range(t1[j * N + i]);
            double n[3], q[3];
            if (bfn_texel_direction((i + 0.5) / N, (j + 0.5) / N, n))
                centres &= bfn_table_lookup(t1, N, 0, n) == t1[j * N + i] &&
                           bfn_table_lookup(t1, N, 0, n) == (float)bfn_best_scale(n, BFN_ERROR_PUBLISHED, q);
        }
    CHECK(exact);
    CHECK(centres);
    unsigned long long s = 11;
    int symmetric = 1;
    for (int k = 0; k < 500; ++k) {
        double n[3], m[3];
        random_direction(&s, n);
        double t = bfn_table_lookup(t1, N, 1, n);
        for (int p = 0; p < 6; ++p) /* the 6 permutations, each with a sign pattern */
            for (int sg = 0; sg < 8; ++sg) {
                static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
                for (int i = 0; i < 3; ++i)
                    m[i] = ((sg >> i) & 1 ? -1.0 : 1.0) * n[perm[p][i]];
                symmetric &= bfn_table_lookup(t1, N, 1, m) == t;
            }
    }
    CHECK(symmetric);
    free(t1);
    free(t2);
}

/* mu(d) for odd d by trial division. */
static int moebius(int d)
{
    int mu = 1;
    for (int p = 3; p <= d; p += 2)
        if (d % p == 0) {
            d /= p;
            if (d % p == 0)
                return 0;
            mu = -mu;
        }
    return mu;
}

static void check_counts(void)
{
    CHECK(bfn_cells_surface() == 256L * 256 * 256 - 254L * 254 * 254);
    long moebius_sum = 0;
    for (int d = 1; d <= 255; d += 2) {
        long multiples = 2 * ((255 / d + 1) / 2); /* odd multiples of d in 1..255, both signs */
        moebius_sum += moebius(d) * multiples * multiples * multiples;
    }
    CHECK(bfn_cells_distinct(2) == moebius_sum);
    long sphere = bfn_cells_sphere();
    long s64 = bfn_cells_sampled(BFN_SAMPLED_NAIVE, 64, 2), s256 = bfn_cells_sampled(BFN_SAMPLED_NAIVE, 256, 2);
    CHECK(s64 < s256 && s256 < sphere);
    long m256 = bfn_cells_sampled(BFN_SAMPLED_MAX, 256, 2);
    CHECK(m256 <= bfn_cells_surface() && m256 > s256);
    CHECK(bfn_cells_sampled(BFN_SAMPLED_NAIVE, 64, 1) == s64);
    for (int e = BFN_SAMPLED_NAIVE; e <= BFN_SAMPLED_BEST_FIT; ++e)
        CHECK_MSG(bfn_cells_sampled(e, 48, 2) == bfn_cells_sampled_direct(e, 48, 2), "encoding %d", e);
}

/* The EXR holds the table's floats; the C header one code per texel, each
 * round(255 t). */
static void check_writers(void)
{
    enum { N = 32 };
    float *t = bfn_table_build(N, BFN_ERROR_PUBLISHED, 2);
    gt_error e;
    CHECK(bfn_table_write_all(check_tmp_dir(), "bfn_test", t, N, "test", &e) == 0);
    char path[4096];
    snprintf(path, sizeof path, "%s/bfn_test.exr", check_tmp_dir());
    image img;
    CHECK(exr_read(path, &img, &e) == 0);
    const float *plane = image_channel_data(&img, CH_BEST_FIT_SCALE);
    CHECK(plane && memcmp(plane, t, sizeof(float) * N * N) == 0);
    image_free(&img);
    snprintf(path, sizeof path, "%s/bfn_test.h", check_tmp_dir());
    FILE *f = fopen(path, "r");
    char text[1 << 16];
    size_t len = f ? fread(text, 1, sizeof text - 1, f) : 0;
    text[len] = 0;
    if (f)
        fclose(f);
    const char *p = strstr(text, "= {\n");
    int codes = 0, match = 1;
    for (p = p ? p + 4 : text + len; *p && *p != '}'; ++codes) {
        long k = strtol(p, (char **)&p, 10);
        match &= codes < N * N && k == lround(t[codes] * 255.0);
        while (*p == ',' || *p == '\n')
            ++p;
    }
    CHECK(codes == N * N && match);
    free(t);
}

int main(void)
{
    check_writers();
    CHECK(bfn_quantize255(1.0) == 1.0 && bfn_quantize255(-1.0) == -1.0 && bfn_code(0.0) == 128);
    CHECK(bfn_code_value(bfn_code(0.3)) == bfn_quantize255(0.3));
    check_searches();
    check_table();
    check_counts();
    return check_report("test_best_fit_normals");
}
