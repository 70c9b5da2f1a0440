/* G-buffer normal encodings (normal_encoding.h). */
#include "best_fit_normals/normal_encoding.h"

#include <math.h>
#include <stdlib.h>

#include "best_fit_normals/best_fit_normals.h"

static const char *const rgb8_names[RGB8_ENCODING_COUNT] = {"naive", "max", "best-fit", "best-fit-bilinear"};

const char *rgb8_encoding_name(int encoding)
{
    return encoding >= 0 && encoding < RGB8_ENCODING_COUNT ? rgb8_names[encoding] : "?";
}

static void normalize3(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < 3; ++i)
        v[i] /= l;
}

void rgb8_encode(rgb8_encoding encoding, const best_fit_table *table, const double n[3], int code[3])
{
    double m = fmax(fabs(n[0]), fmax(fabs(n[1]), fabs(n[2]))), scale = 1.0;
    if (encoding != RGB8_NAIVE)
        scale = 1.0 / m;
    if (encoding == RGB8_BEST_FIT_POINT || encoding == RGB8_BEST_FIT_BILINEAR)
        scale *= bfn_table_lookup(table->table, table->size, encoding == RGB8_BEST_FIT_BILINEAR, n);
    for (int i = 0; i < 3; ++i)
        code[i] = bfn_code(n[i] * scale);
}

void rgb8_decode(const int code[3], double n[3])
{
    for (int i = 0; i < 3; ++i)
        n[i] = bfn_code_value(code[i]);
    normalize3(n);
}

static double sign_not_zero(double x)
{
    return x >= 0.0 ? 1.0 : -1.0;
}

/* n on the octahedron, the lower hemisphere folded: p in [-1, 1]^2. */
static void octahedral_point(const double n[3], double p[2])
{
    double l1 = fabs(n[0]) + fabs(n[1]) + fabs(n[2]);
    p[0] = n[0] / l1;
    p[1] = n[1] / l1;
    if (n[2] < 0.0) {
        double x = p[0], y = p[1];
        p[0] = (1.0 - fabs(y)) * sign_not_zero(x);
        p[1] = (1.0 - fabs(x)) * sign_not_zero(y);
    }
}

void octahedral_decode(const int code[2], int bits, double n[3])
{
    double s = (double)((1 << (bits - 1)) - 1);
    double x = fmax(-1.0, code[0] / s), y = fmax(-1.0, code[1] / s);
    n[0] = x;
    n[1] = y;
    n[2] = 1.0 - fabs(x) - fabs(y);
    if (n[2] < 0.0) {
        n[0] = (1.0 - fabs(y)) * sign_not_zero(x);
        n[1] = (1.0 - fabs(x)) * sign_not_zero(y);
    }
    normalize3(n);
}

static double decoded_cosine(const int code[2], int bits, const double n[3])
{
    double d[3];
    octahedral_decode(code, bits, d);
    return d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
}

void octahedral_encode(const double n[3], int bits, int precise, int code[2])
{
    double s = (double)((1 << (bits - 1)) - 1), p[2];
    octahedral_point(n, p);
    for (int i = 0; i < 2; ++i)
        code[i] = (int)floor(fmin(1.0, fmax(-1.0, p[i])) * s + 0.5);
    if (!precise)
        return;
    int base[2] = {(int)floor(p[0] * s), (int)floor(p[1] * s)};
    double best_cos = -2.0;
    for (int k = 0; k < 4; ++k) {
        int c[2] = {base[0] + (k & 1), base[1] + (k >> 1)};
        if (abs(c[0]) > (int)s || abs(c[1]) > (int)s)
            continue;
        double cs = decoded_cosine(c, bits, n);
        if (cs > best_cos) {
            best_cos = cs;
            code[0] = c[0];
            code[1] = c[1];
        }
    }
}
