/* The cell counts of best_fit_normals_cells.h. */
#include "best_fit_normals/best_fit_normals_cells.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "best_fit_normals/best_fit_normals.h"

/* |2 c - 255|: the cell's value in units of 1/255, always odd. */
static int odd_magnitude(int c)
{
    return abs(2 * c - 255);
}

/* The box of cell c spans [m - 1, m + 1] / 255 in |value| (m = odd_magnitude). */
static int box_crosses_unit_sphere(int a, int b, int c)
{
    int m[3] = {odd_magnitude(a), odd_magnitude(b), odd_magnitude(c)};
    long lo = 0, hi = 0;
    for (int i = 0; i < 3; ++i) {
        lo += (long)(m[i] - 1) * (m[i] - 1);
        hi += (long)(m[i] + 1) * (m[i] + 1);
    }
    return lo <= 255L * 255L && hi >= 255L * 255L;
}

long bfn_cells_sphere(void)
{
    long n = 0;
    for (int a = 0; a < 256; ++a)
        for (int b = 0; b < 256; ++b)
            for (int c = 0; c < 256; ++c)
                n += box_crosses_unit_sphere(a, b, c);
    return n;
}

long bfn_cells_surface(void)
{
    long n = 0;
    for (int a = 0; a < 256; ++a)
        for (int b = 0; b < 256; ++b)
            for (int c = 0; c < 256; ++c)
                n += (a == 0 || a == 255 || b == 0 || b == 255 || c == 0 || c == 255);
    return n;
}

static int gcd(int a, int b)
{
    while (b) {
        int t = a % b;
        a = b;
        b = t;
    }
    return a;
}

long bfn_cells_distinct(int threads)
{
    long n = 0;
#pragma omp parallel for reduction(+ : n) num_threads(threads)
    for (int a = 0; a < 256; ++a)
        for (int b = 0; b < 256; ++b)
            for (int c = 0; c < 256; ++c)
                n += gcd(gcd(odd_magnitude(a), odd_magnitude(b)), odd_magnitude(c)) == 1;
    return n;
}

/* The unit direction of texel (i, j) of cube face f (axis f / 2, sign by f & 1). */
static void face_direction(int f, int i, int j, int face, double n[3])
{
    int axis = f / 2;
    double v[3];
    v[axis] = (f & 1) ? -1.0 : 1.0;
    v[(axis + 1) % 3] = 2.0 * (i + 0.5) / face - 1.0;
    v[(axis + 2) % 3] = 2.0 * (j + 0.5) / face - 1.0;
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; ++k)
        n[k] = v[k] / l;
}

static unsigned sampled_cell(bfn_sampled_encoding encoding, const double n[3])
{
    double x[3], m = fmax(fabs(n[0]), fmax(fabs(n[1]), fabs(n[2])));
    if (encoding == BFN_SAMPLED_BEST_FIT)
        bfn_best_scale(n, BFN_ERROR_PUBLISHED, x);
    else
        for (int k = 0; k < 3; ++k)
            x[k] = encoding == BFN_SAMPLED_MAX ? n[k] / m : n[k];
    return ((unsigned)bfn_code(x[0]) << 16) | ((unsigned)bfn_code(x[1]) << 8) | (unsigned)bfn_code(x[2]);
}

static long count_bits(const uint8_t *bits)
{
    long n = 0;
    for (int i = 0; i < BFN_CELL_COUNT / 8; ++i)
        n += __builtin_popcount(bits[i]);
    return n;
}

static void set_cell(uint8_t *bits, unsigned id)
{
    __atomic_fetch_or(&bits[id >> 3], (uint8_t)(1u << (id & 7)), __ATOMIC_RELAXED);
}

static unsigned cell_id(const int c[3])
{
    return ((unsigned)c[0] << 16) | ((unsigned)c[1] << 8) | (unsigned)c[2];
}

/* The 48 images of a cell under the cube's symmetries: the 6 axis
 * permutations, each with the 8 reflections c -> 255 - c. */
static void set_cell_images(uint8_t *bits, unsigned id)
{
    static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    int c[3] = {(int)(id >> 16), (int)((id >> 8) & 255), (int)(id & 255)};
    for (int p = 0; p < 6; ++p)
        for (int r = 0; r < 8; ++r) {
            int d[3];
            for (int i = 0; i < 3; ++i)
                d[i] = (r >> i) & 1 ? 255 - c[perm[p][i]] : c[perm[p][i]];
            set_cell(bits, cell_id(d));
        }
}

static long sampled_count(uint8_t *bits)
{
    long n = count_bits(bits);
    free(bits);
    return n;
}

long bfn_cells_sampled_direct(bfn_sampled_encoding encoding, int face, int threads)
{
    uint8_t *bits = calloc(BFN_CELL_COUNT / 8, 1);
    if (!bits)
        return -1;
#pragma omp parallel for schedule(dynamic, 8) num_threads(threads)
    for (int row = 0; row < 6 * face; ++row)
        for (int j = 0; j < face; ++j) {
            double n[3];
            face_direction(row / face, row % face, j, face, n);
            set_cell(bits, sampled_cell(encoding, n));
        }
    return sampled_count(bits);
}

/* Face +z, texels with x >= y >= 0 (i >= j >= face / 2): a fundamental
 * domain of the cubemap's texel centres under the 48 symmetries, which the
 * encodings commute with; each cell found adds its 48 images. */
long bfn_cells_sampled(bfn_sampled_encoding encoding, int face, int threads)
{
    uint8_t *bits = calloc(BFN_CELL_COUNT / 8, 1);
    if (!bits)
        return -1;
#pragma omp parallel for schedule(dynamic, 8) num_threads(threads)
    for (int i = face / 2; i < face; ++i)
        for (int j = face / 2; j <= i; ++j) {
            double n[3];
            face_direction(4, i, j, face, n);
            set_cell_images(bits, sampled_cell(encoding, n));
        }
    return sampled_count(bits);
}
