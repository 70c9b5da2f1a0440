/* Best-fit normals: the talk's search, the exhaustive search and the table
 * (best_fit_normals.h). */
#include "best_fit_normals/best_fit_normals.h"

#include <math.h>
#include <stdlib.h>

static const char *const metric_names[BFN_ERROR_COUNT] = {"published", "angle"};

const char *bfn_error_metric_name(int metric)
{
    return metric >= 0 && metric < BFN_ERROR_COUNT ? metric_names[metric] : "?";
}

int bfn_code(double c)
{
    double w = fmin(1.0, fmax(0.0, c * 0.5 + 0.5));
    return (int)floor(w * 255.0 + 0.5);
}

double bfn_code_value(int code)
{
    return code / 255.0 * 2.0 - 1.0;
}

double bfn_quantize255(double c)
{
    return bfn_code_value(bfn_code(c));
}

double bfn_angle(const double a[3], const double b[3])
{
    double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
    return atan2(sqrt(cx * cx + cy * cy + cz * cz), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

static double max_abs(const double n[3])
{
    return fmax(fabs(n[0]), fmax(fabs(n[1]), fabs(n[2])));
}

/* The talk's probe error max_i |q_i - p_i| / t, or the angle to n. */
static double probe_error(const double n[3], const double p[3], const double q[3], double t, bfn_error_metric metric)
{
    if (metric == BFN_ERROR_ANGLE)
        return bfn_angle(q, n);
    double e = 0.0;
    for (int i = 0; i < 3; ++i)
        e = fmax(e, fabs(q[i] - p[i]) / t);
    return e;
}

double bfn_best_scale(const double n[3], bfn_error_metric metric, double q[3])
{
    double m = max_abs(n), best = INFINITY, best_t = 1.0;
    for (double step = 1.5; step <= 127.5; step += 1.0) {
        double t = step / 127.5, p[3], qp[3];
        for (int i = 0; i < 3; ++i) {
            p[i] = n[i] / m * t;
            qp[i] = bfn_quantize255(p[i]);
        }
        double e = probe_error(n, p, qp, t, metric);
        if (e < best) {
            best = e;
            best_t = t;
            for (int i = 0; i < 3; ++i)
                q[i] = qp[i];
        }
    }
    return best_t;
}

/* In the slab whose major code is `major_code`, the 3 x 3 cells about the
 * ray's crossing; keeps the closest in angle. */
static void search_slab(const double n[3], int axis, int major_code, double *best, double q[3])
{
    double major = bfn_code_value(major_code), scale = major / n[axis];
    int centre[3];
    for (int i = 0; i < 3; ++i)
        centre[i] = bfn_code(n[i] * scale);
    for (int di = -1; di <= 1; ++di)
        for (int dj = -1; dj <= 1; ++dj) {
            int code[3] = {centre[0], centre[1], centre[2]}, k = 0;
            for (int i = 0; i < 3; ++i)
                if (i != axis)
                    code[i] += (k++ == 0) ? di : dj;
            if (code[0] < 0 || code[0] > 255 || code[1] < 0 || code[1] > 255 || code[2] < 0 || code[2] > 255)
                continue;
            double c[3] = {bfn_code_value(code[0]), bfn_code_value(code[1]), bfn_code_value(code[2])};
            double e = bfn_angle(c, n);
            if (e < *best) {
                *best = e;
                for (int i = 0; i < 3; ++i)
                    q[i] = c[i];
            }
        }
}

double bfn_best_cell_exhaustive(const double n[3], double q[3])
{
    int axis = fabs(n[0]) >= fabs(n[1]) ? (fabs(n[0]) >= fabs(n[2]) ? 0 : 2) : (fabs(n[1]) >= fabs(n[2]) ? 1 : 2);
    double best = INFINITY;
    for (int k = 0; k < 128; ++k) /* major codes on n's side of the centre */
        search_slab(n, axis, n[axis] > 0.0 ? 128 + k : 127 - k, &best, q);
    return best;
}

int bfn_texel_direction(double u, double v, double n[3])
{
    double a = u, b = u * v, c2 = 1.0 - a * a - b * b;
    if (c2 < a * a)
        return 0;
    n[0] = a;
    n[1] = b;
    n[2] = sqrt(c2);
    return 1;
}

/* Row j: each valid texel's search, then the invalid tail repeats the last
 * valid texel (u grows along the row, so the valid texels come first). */
static void build_row(float *row, int size, int j, bfn_error_metric metric)
{
    double v = (j + 0.5) / size, last = 1.0;
    for (int i = 0; i < size; ++i) {
        double n[3], q[3];
        if (bfn_texel_direction((i + 0.5) / size, v, n))
            last = bfn_best_scale(n, metric, q);
        row[i] = (float)last;
    }
}

float *bfn_table_build(int size, bfn_error_metric metric, int threads)
{
    float *table = malloc((size_t)size * (size_t)size * sizeof *table);
    if (!table)
        return NULL;
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
    for (int j = 0; j < size; ++j)
        build_row(table + (size_t)j * (size_t)size, size, j, metric);
    return table;
}

/* The shader's texture coordinates (Appendix A, CompressNormalToUnsignedGBuffer):
 * the two smaller |components|, the larger first, the second divided by it. */
static void table_coordinates(const double n[3], double *u, double *v)
{
    double x = fabs(n[0]), y = fabs(n[1]), z = fabs(n[2]), m = fmax(x, fmax(y, z));
    double a = z < m ? (y < m ? y : x) : x, b = z < m ? z : y;
    if (a < b) {
        double s = a;
        a = b;
        b = s;
    }
    *u = a;
    *v = a > 0.0 ? b / a : 0.0;
}

static double texel(const float *table, int size, int i, int j)
{
    i = i < 0 ? 0 : (i >= size ? size - 1 : i);
    j = j < 0 ? 0 : (j >= size ? size - 1 : j);
    return table[(size_t)j * (size_t)size + (size_t)i];
}

double bfn_table_lookup(const float *table, int size, int bilinear, const double n[3])
{
    double u, v;
    table_coordinates(n, &u, &v);
    double x = u * size - 0.5, y = v * size - 0.5;
    if (!bilinear)
        return texel(table, size, (int)floor(x + 0.5), (int)floor(y + 0.5));
    int i = (int)floor(x), j = (int)floor(y);
    double fx = x - i, fy = y - j;
    return (1 - fy) * ((1 - fx) * texel(table, size, i, j) + fx * texel(table, size, i + 1, j)) +
           fy * ((1 - fx) * texel(table, size, i, j + 1) + fx * texel(table, size, i + 1, j + 1));
}
