/* LDR-FLIP and HDR-FLIP (Andersson et al. 2020, 2021); see flip.h for the
 * pipeline followed, equation by equation. */
#include "metrics/flip.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/vec3.h" /* M_PI */
#include "metrics/image_error.h"

/* ---- colour spaces ---------------------------------------------------- */

/* Linear sRGB (IEC 61966-2-1 primaries) to CIE XYZ under D65, as the exact
 * fractions the FLIP papers' code uses; its rows sum to the white point, so
 * a grey has a* = b* = 0. */
static const double rgb_to_xyz[3][3] = {
    {10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0},
    {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0},
    {1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0}};

static void mat3_apply(const double m[3][3], const double v[3], double out[3])
{
    for (int i = 0; i < 3; ++i)
        out[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
}

/* The white point: XYZ of linear RGB (1, 1, 1). */
static void white_point(double w[3])
{
    const double one[3] = {1.0, 1.0, 1.0};
    mat3_apply(rgb_to_xyz, one, w);
}

/* The inverse of rgb_to_xyz by its adjugate. */
static void xyz_to_rgb_matrix(double inv[3][3])
{
    const double(*m)[3] = rgb_to_xyz;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            inv[i][j] = m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];
        }
    double det = m[0][0] * inv[0][0] + m[0][1] * inv[1][0] + m[0][2] * inv[2][0];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            inv[i][j] /= det;
}

/* Linear RGB -> YCxCz (step 1). */
static void rgb_to_ycxcz(const double rgb[3], const double white[3], double out[3])
{
    double xyz[3];
    mat3_apply(rgb_to_xyz, rgb, xyz);
    double x = xyz[0] / white[0], y = xyz[1] / white[1], z = xyz[2] / white[2];
    out[0] = 116.0 * y - 16.0;
    out[1] = 500.0 * (x - y);
    out[2] = 200.0 * (y - z);
}

/* YCxCz -> XYZ / white (the inverse of step 1's linear map). */
static void ycxcz_to_relative_xyz(const double c[3], double out[3])
{
    out[1] = (c[0] + 16.0) / 116.0;
    out[0] = out[1] + c[1] / 500.0;
    out[2] = out[1] - c[2] / 200.0;
}

/* CIELAB's f(t): the cube root above (6/29)^3, the linear segment below. */
static double lab_f(double t)
{
    const double delta = 6.0 / 29.0;
    return t > delta * delta * delta ? cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

/* Linear RGB -> Hunt-adjusted L*a*b* (step 3). */
static void rgb_to_hunt_lab(const double rgb[3], const double white[3], double out[3])
{
    double xyz[3];
    mat3_apply(rgb_to_xyz, rgb, xyz);
    double fx = lab_f(xyz[0] / white[0]), fy = lab_f(xyz[1] / white[1]), fz = lab_f(xyz[2] / white[2]);
    out[0] = 116.0 * fy - 16.0;
    out[1] = 0.01 * out[0] * 500.0 * (fx - fy);
    out[2] = 0.01 * out[0] * 200.0 * (fy - fz);
}

static double hyab(const double p[3], const double q[3])
{
    double da = p[1] - q[1], db = p[2] - q[2];
    return fabs(p[0] - q[0]) + sqrt(da * da + db * db);
}

/* c_max = HyAB(green, blue)^q_c of the Hunt-adjusted primaries. */
static double colour_cmax(const double white[3])
{
    const double green[3] = {0.0, 1.0, 0.0}, blue[3] = {0.0, 0.0, 1.0};
    double g[3], b[3];
    rgb_to_hunt_lab(green, white, g);
    rgb_to_hunt_lab(blue, white, b);
    return pow(hyab(g, b), FLIP_QC);
}

/* Step 4's compression of e = HyAB^q_c to [0, 1]. */
static double compress_colour(double e, double cmax)
{
    double knee = FLIP_PC * cmax;
    return e < knee ? FLIP_PT / knee * e : FLIP_PT + (e - knee) / (cmax - knee) * (1.0 - FLIP_PT);
}

/* ---- kernels ---------------------------------------------------------- */

enum { CSF_TERMS = 2, MAX_RADIUS = 256 };

/* One channel's CSF as separable terms: sum_t weight[t] g_t(x) g_t(y), each
 * g_t a 1-D kernel summing to 1, the weights summing to 1. */
typedef struct {
    int terms;
    double weight[CSF_TERMS];
    double *taps[CSF_TERMS]; /* 2 radius + 1 each */
} csf_kernel;

typedef struct {
    int csf_radius, feature_radius;
    csf_kernel csf[3]; /* achromatic, red-green, blue-yellow */
    /* 1-D feature kernels: the Gaussian (sum 1), its first and second
     * derivatives (positive taps sum 1, negative -1) */
    double *gauss, *edge, *point;
    double *storage;
} flip_kernels;

/* a1, b1, a2, b2 of the three CSFs (eq. 2). */
static const double csf_parameters[3][4] = {{1.0, 0.0047, 0.0, 1e-5}, {1.0, 0.0053, 0.0, 1e-5},
                                            {34.1, 0.04, 13.5, 0.025}};

static int csf_radius(double ppd)
{
    const double b_max = 0.04;
    return (int)ceil(3.0 * sqrt(b_max / (2.0 * M_PI * M_PI)) * ppd);
}

/* exp(-pi^2 (k / ppd)^2 / b) for k = -r..r into taps; returns their sum. */
static double csf_gaussian(double b, double ppd, int r, double *taps)
{
    double sum = 0.0;
    for (int k = -r; k <= r; ++k) {
        double x = k / ppd;
        taps[k + r] = exp(-M_PI * M_PI * x * x / b);
        sum += taps[k + r];
    }
    return sum;
}

/* The normalised separable terms of channel c. */
static void csf_build(int c, double ppd, int r, csf_kernel *k)
{
    const double *p = csf_parameters[c];
    double total = 0.0;
    k->terms = p[2] > 0.0 ? 2 : 1;
    for (int t = 0; t < k->terms; ++t) {
        double a = p[2 * t], b = p[2 * t + 1];
        double sum = csf_gaussian(b, ppd, r, k->taps[t]);
        for (int i = 0; i <= 2 * r; ++i)
            k->taps[t][i] /= sum;
        k->weight[t] = a * sqrt(M_PI / b) * sum * sum; /* this term's share of the 2-D kernel's sum */
        total += k->weight[t];
    }
    for (int t = 0; t < k->terms; ++t)
        k->weight[t] /= total;
}

/* Scales the positive taps to sum 1 and the negative ones to sum -1. */
static void normalise_signed(double *taps, int n)
{
    double pos = 0.0, neg = 0.0;
    for (int i = 0; i < n; ++i)
        taps[i] > 0.0 ? (pos += taps[i]) : (neg -= taps[i]);
    for (int i = 0; i < n; ++i)
        taps[i] = taps[i] > 0.0 ? taps[i] / pos : taps[i] < 0.0 ? taps[i] / neg : 0.0;
}

/* The Gaussian of sigma = 0.5 w ppd, its first derivative -x g and second
 * (x^2 / sigma^2 - 1) g (section 4.2). */
static void feature_build(double ppd, int r, flip_kernels *k)
{
    double sigma = 0.5 * FLIP_EDGE_WIDTH * ppd, sum = 0.0;
    for (int x = -r; x <= r; ++x) {
        double g = exp(-(double)(x * x) / (2.0 * sigma * sigma));
        k->gauss[x + r] = g;
        k->edge[x + r] = -x * g;
        k->point[x + r] = ((double)(x * x) / (sigma * sigma) - 1.0) * g;
        sum += g;
    }
    for (int i = 0; i <= 2 * r; ++i)
        k->gauss[i] /= sum;
    normalise_signed(k->edge, 2 * r + 1);
    normalise_signed(k->point, 2 * r + 1);
}

static int kernels_init(double ppd, flip_kernels *k)
{
    memset(k, 0, sizeof *k);
    k->csf_radius = csf_radius(ppd);
    k->feature_radius = (int)ceil(3.0 * 0.5 * FLIP_EDGE_WIDTH * ppd);
    if (!(ppd > 0.0) || k->csf_radius > MAX_RADIUS || k->feature_radius > MAX_RADIUS)
        return -1;
    size_t nc = 2 * (size_t)k->csf_radius + 1, nf = 2 * (size_t)k->feature_radius + 1;
    k->storage = malloc(sizeof *k->storage * (6 * nc + 3 * nf));
    if (!k->storage)
        return -1;
    for (int c = 0; c < 3; ++c) {
        k->csf[c].taps[0] = k->storage + (2 * (size_t)c) * nc;
        k->csf[c].taps[1] = k->storage + (2 * (size_t)c + 1) * nc;
        csf_build(c, ppd, k->csf_radius, &k->csf[c]);
    }
    k->gauss = k->storage + 6 * nc, k->edge = k->gauss + nf, k->point = k->edge + nf;
    feature_build(ppd, k->feature_radius, k);
    return 0;
}

/* ---- separable convolution -------------------------------------------- */

static int clampi(int v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : v; }

/* One row of in convolved along x with taps k (2r+1), edges replicated:
 * clamped indices only within r of an edge. */
static void row_pass(const double *in, int w, const double *k, int r, double *out)
{
    for (int x = 0; x < w; ++x) {
        double s = 0.0;
        if (x >= r && x < w - r) {
            const double *p = in + x - r;
            for (int t = 0; t <= 2 * r; ++t)
                s += k[t] * p[t];
        } else
            for (int t = -r; t <= r; ++t)
                s += k[t + r] * in[clampi(x + t, 0, w - 1)];
        out[x] = s;
    }
}

/* in convolved along x (into out). */
static void convolve_x(const double *in, int w, int h, const double *k, int r, double *out)
{
#pragma omp parallel for schedule(static)
    for (int y = 0; y < h; ++y)
        row_pass(in + (size_t)y * (size_t)w, w, k, r, out + (size_t)y * (size_t)w);
}

/* in convolved along y (into out): each output row a weighted sum of 2r+1
 * whole rows, in tap order, the rows beyond the edges replicated. */
static void convolve_y(const double *in, int w, int h, const double *k, int r, double *out)
{
#pragma omp parallel for schedule(static)
    for (int y = 0; y < h; ++y) {
        double *o = out + (size_t)y * (size_t)w;
        for (int x = 0; x < w; ++x)
            o[x] = 0.0;
        for (int t = -r; t <= r; ++t) {
            const double *src = in + (size_t)clampi(y + t, 0, h - 1) * (size_t)w;
            double kt = k[t + r];
            for (int x = 0; x < w; ++x)
                o[x] += kt * src[x];
        }
    }
}

/* ---- one image through both pipelines --------------------------------- */

/* What the final error needs of one image: its Hunt-adjusted L*a*b* after
 * the CSFs, and the magnitudes of its edge and point responses. */
typedef struct {
    float *lab[3], *edge, *point;
} prepared_image;

/* Scratch shared by the two images: three filtered YCxCz planes (floats),
 * and planes of doubles: the channel filtered, two passes, two responses. */
typedef struct {
    float *filtered[3];
    double *plane, *pass[2], *response[2];
} flip_scratch;

/* Whether the image is grey by construction: its three planes are one. */
static int is_grey(const flip_image *im) { return im->plane[0] == im->plane[1] && im->plane[1] == im->plane[2]; }

/* Channel c of YCxCz (step 1) into s->plane. */
static void to_ycxcz(const flip_image *im, int c, const double white[3], flip_scratch *s)
{
    size_t n = (size_t)im->width * (size_t)im->height;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; ++i) {
        double rgb[3] = {im->plane[0][i], im->plane[1][i], im->plane[2][i]}, ycc[3];
        rgb_to_ycxcz(rgb, white, ycc);
        s->plane[i] = ycc[c];
    }
}

/* Step 2: each channel through its CSF into s->filtered. A grey image's Cx
 * and Cz are 0 (up to the rounding of the white point), and stay 0. */
static void filter_csf(const flip_image *im, const flip_kernels *k, const double white[3], flip_scratch *s)
{
    int w = im->width, h = im->height, r = k->csf_radius;
    size_t n = (size_t)w * (size_t)h;
    for (int c = 0; c < 3; ++c) {
        for (size_t i = 0; i < n; ++i)
            s->filtered[c][i] = 0.0f;
        if (c > 0 && is_grey(im))
            continue;
        to_ycxcz(im, c, white, s);
        for (int t = 0; t < k->csf[c].terms; ++t) {
            convolve_x(s->plane, w, h, k->csf[c].taps[t], r, s->pass[0]);
            convolve_y(s->pass[0], w, h, k->csf[c].taps[t], r, s->pass[1]);
            for (size_t i = 0; i < n; ++i)
                s->filtered[c][i] = (float)(s->filtered[c][i] + k->csf[c].weight[t] * s->pass[1][i]);
        }
    }
}

/* Filtered YCxCz -> linear RGB clamped to [0, 1] -> Hunt-adjusted L*a*b*. */
static void to_hunt_lab(const float *const filtered[3], size_t n, const double white[3], float *lab[3])
{
    double inv[3][3];
    xyz_to_rgb_matrix(inv);
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; ++i) {
        double c[3] = {filtered[0][i], filtered[1][i], filtered[2][i]}, rel[3], xyz[3], rgb[3], out[3];
        ycxcz_to_relative_xyz(c, rel);
        for (int k = 0; k < 3; ++k)
            xyz[k] = rel[k] * white[k];
        mat3_apply((const double(*)[3])inv, xyz, rgb);
        for (int k = 0; k < 3; ++k)
            rgb[k] = fmin(1.0, fmax(0.0, rgb[k]));
        rgb_to_hunt_lab(rgb, white, out);
        for (int k = 0; k < 3; ++k)
            lab[k][i] = (float)out[k];
    }
}

/* |(a, b)| of two response planes into out. */
static void magnitude(const double *a, const double *b, size_t n, float *out)
{
    for (size_t i = 0; i < n; ++i)
        out[i] = (float)sqrt(a[i] * a[i] + b[i] * b[i]);
}

/* The x and y responses of the luminance (s->plane) to the derivative
 * kernel d (Gaussian across), their magnitude into out. The Gaussian pass
 * across is shared by the edge and point kernels: pass[0] holds s->plane
 * smoothed along y, pass[1] along x (see detect_features). */
static void feature_magnitude(const flip_kernels *k, int w, int h, const double *d, flip_scratch *s, double *rx,
                              double *ry, float *out)
{
    int r = k->feature_radius;
    convolve_x(s->pass[0], w, h, d, r, rx);
    convolve_y(s->pass[1], w, h, d, r, ry);
    magnitude(rx, ry, (size_t)w * (size_t)h, out);
}

/* Section 4.2 on the luminance Y/Yn = (Y' + 16) / 116 of the unfiltered
 * image: |edge| and |point|. */
static void detect_features(const flip_image *im, const flip_kernels *k, const double white[3], flip_scratch *s,
                            prepared_image *p)
{
    int w = im->width, h = im->height, r = k->feature_radius;
    size_t n = (size_t)w * (size_t)h;
    to_ycxcz(im, 0, white, s);
    for (size_t i = 0; i < n; ++i)
        s->plane[i] = (s->plane[i] + 16.0) / 116.0;
    convolve_y(s->plane, w, h, k->gauss, r, s->pass[0]);
    convolve_x(s->plane, w, h, k->gauss, r, s->pass[1]);
    feature_magnitude(k, w, h, k->edge, s, s->response[0], s->response[1], p->edge);
    feature_magnitude(k, w, h, k->point, s, s->response[0], s->response[1], p->point);
}

static void prepare(const flip_image *im, const flip_kernels *k, const double white[3], flip_scratch *s,
                    prepared_image *p)
{
    filter_csf(im, k, white, s);
    to_hunt_lab((const float *const *)s->filtered, (size_t)im->width * (size_t)im->height, white, p->lab);
    detect_features(im, k, white, s, p);
}

/* FLIP = dE_c^(1 - dE_f) of one pixel (eq. 7). */
static float pixel_flip(const prepared_image *r, const prepared_image *t, size_t i, double cmax)
{
    double lr[3] = {r->lab[0][i], r->lab[1][i], r->lab[2][i]}, lt[3] = {t->lab[0][i], t->lab[1][i], t->lab[2][i]};
    double colour = compress_colour(pow(hyab(lr, lt), FLIP_QC), cmax);
    double edge = fabs((double)r->edge[i] - t->edge[i]), point = fabs((double)r->point[i] - t->point[i]);
    double feature = pow(fmax(edge, point) / sqrt(2.0), FLIP_QF);
    return (float)pow(colour, 1.0 - feature);
}

/* ---- LDR-FLIP --------------------------------------------------------- */

/* Every plane of the comparison in one block: 2 x 5 prepared planes and
 * 3 filtered ones (floats), 5 planes of doubles. */
typedef struct {
    prepared_image image[2];
    flip_scratch scratch;
    void *block;
} ldr_buffers;

static int buffers_init(ldr_buffers *b, size_t n)
{
    memset(b, 0, sizeof *b);
    b->block = malloc(n * (13 * sizeof(float) + 5 * sizeof(double)));
    if (!b->block)
        return -1;
    double *d = b->block;
    double **doubles[5] = {&b->scratch.plane, &b->scratch.pass[0], &b->scratch.pass[1], &b->scratch.response[0],
                           &b->scratch.response[1]};
    for (int p = 0; p < 5; ++p)
        *doubles[p] = d + (size_t)p * n;
    float *f = (float *)(d + 5 * n);
    float **floats[13] = {&b->image[0].lab[0], &b->image[0].lab[1], &b->image[0].lab[2], &b->image[0].edge,
                          &b->image[0].point,  &b->image[1].lab[0], &b->image[1].lab[1], &b->image[1].lab[2],
                          &b->image[1].edge,   &b->image[1].point,  &b->scratch.filtered[0],
                          &b->scratch.filtered[1], &b->scratch.filtered[2]};
    for (int p = 0; p < 13; ++p)
        *floats[p] = f + (size_t)p * n;
    return 0;
}

int flip_ldr(const flip_image *reference, const flip_image *test, double ppd, const char *what, float *map,
             gt_error *e)
{
    if (reference->width != test->width || reference->height != test->height)
        return gt_error_set(e, what, "FLIP of a %dx%d image against a %dx%d reference", test->width, test->height,
                            reference->width, reference->height);
    flip_kernels k;
    if (kernels_init(ppd, &k) != 0) {
        free(k.storage);
        return gt_error_set(e, what, "FLIP at %g pixels per degree: out of memory or out of range", ppd);
    }
    size_t n = (size_t)reference->width * (size_t)reference->height;
    ldr_buffers b;
    if (buffers_init(&b, n) != 0) {
        free(k.storage);
        return gt_error_set(e, what, "out of memory");
    }
    double white[3];
    white_point(white);
    prepare(reference, &k, white, &b.scratch, &b.image[0]);
    prepare(test, &k, white, &b.scratch, &b.image[1]);
    double cmax = colour_cmax(white);
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; ++i)
        map[i] = pixel_flip(&b.image[0], &b.image[1], i, cmax);
    free(b.block);
    free(k.storage);
    return 0;
}

/* ---- HDR-FLIP --------------------------------------------------------- */

static const double aces_k[6] = {0.6 * 0.6 * 2.51, 0.6 * 0.03, 0.0, 0.6 * 0.6 * 2.43, 0.6 * 0.59, 0.14};

double flip_tone_map(double x)
{
    const double *k = aces_k;
    double y = (k[0] * x * x + k[1] * x + k[2]) / (k[3] * x * x + k[4] * x + k[5]);
    return fmin(1.0, fmax(0.0, y));
}

/* T(x) = t is (k0 - k3 t) x^2 + (k1 - k4 t) x + (k2 - k5 t) = 0: the
 * positive root of x^2 + c0 x + c1 = 0. */
double flip_tone_map_inverse(double t)
{
    const double *k = aces_k;
    double c0 = (k[1] - k[4] * t) / (k[0] - k[3] * t), c1 = (k[2] - k[5] * t) / (k[0] - k[3] * t);
    return -0.5 * c0 + sqrt(0.25 * c0 * c0 - c1);
}

static int compare_floats(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* The median of values[0..count) (sorted in place; the mean of the two
 * middle ones when count is even). */
static double median(float *values, size_t count)
{
    qsort(values, count, sizeof *values, compare_floats);
    return count % 2 ? values[count / 2] : 0.5 * ((double)values[count / 2 - 1] + values[count / 2]);
}

static double luminance(const flip_image *im, size_t i)
{
    return 0.2126 * fmax(0.0f, im->plane[0][i]) + 0.7152 * fmax(0.0f, im->plane[1][i]) +
           0.0722 * fmax(0.0f, im->plane[2][i]);
}

/* The reference's luminances inside the mask (only the positive ones with
 * `positive`) into y; returns their count. */
static size_t gather_luminance(const flip_image *im, const float *mask, int positive, float *y)
{
    size_t n = (size_t)im->width * (size_t)im->height, count = 0;
    for (size_t i = 0; i < n; ++i) {
        double v = luminance(im, i);
        if (metrics_in_mask(mask, i) && (!positive || v > 0.0))
            y[count++] = (float)v;
    }
    return count;
}

flip_exposures flip_exposure_range(const flip_image *reference, const float *mask)
{
    flip_exposures x = {0.0, 0.0, 2};
    size_t n = (size_t)reference->width * (size_t)reference->height;
    float *y = malloc(sizeof *y * (n ? n : 1));
    size_t count = y ? gather_luminance(reference, mask, 0, y) : 0;
    double y_median = count ? median(y, count) : 0.0, y_max = count ? y[count - 1] : 0.0;
    if (y_max > 0.0 && !(y_median > 0.0)) {
        count = gather_luminance(reference, mask, 1, y);
        y_median = median(y, count);
    }
    free(y);
    if (!(y_max > 0.0))
        return x;
    double xt = flip_tone_map_inverse(FLIP_EXPOSURE_T);
    x.start = log2(xt / y_max);
    x.stop = log2(xt / y_median);
    double steps = ceil(x.stop - x.start);
    x.count = steps > 2.0 ? (int)steps : 2;
    return x;
}

/* 2^c v tone mapped, for each distinct plane of im, into planes of out. */
static void expose(const flip_image *im, double exposure, float *storage, flip_image *out)
{
    size_t n = (size_t)im->width * (size_t)im->height;
    double scale = exp2(exposure);
    *out = *im;
    for (int c = 0; c < 3; ++c) {
        int same = c > 0 && im->plane[c] == im->plane[c - 1];
        out->plane[c] = same ? out->plane[c - 1] : storage + (size_t)c * n;
        if (same)
            continue;
        float *dst = storage + (size_t)c * n;
        for (size_t i = 0; i < n; ++i)
            dst[i] = (float)flip_tone_map(scale * fmax(0.0f, im->plane[c][i]));
    }
}

int flip_hdr(const flip_image *reference, const flip_image *test, flip_exposures exposures, double ppd,
             const char *what, float *map, gt_error *e)
{
    size_t n = (size_t)reference->width * (size_t)reference->height;
    if (reference->width != test->width || reference->height != test->height)
        return flip_ldr(reference, test, ppd, what, map, e); /* its size error */
    float *storage = malloc(sizeof *storage * 7 * n);
    if (!storage)
        return gt_error_set(e, what, "out of memory");
    double step = (exposures.stop - exposures.start) / (exposures.count > 1 ? exposures.count - 1 : 1);
    int rc = 0;
    for (int x = 0; x < exposures.count && rc == 0; ++x) {
        flip_image r, t;
        expose(reference, exposures.start + x * step, storage, &r);
        expose(test, exposures.start + x * step, storage + 3 * n, &t);
        float *ldr = x == 0 ? map : storage + 6 * n;
        rc = flip_ldr(&r, &t, ppd, what, ldr, e);
        for (size_t i = 0; rc == 0 && x > 0 && i < n; ++i)
            map[i] = fmaxf(map[i], ldr[i]);
    }
    free(storage);
    return rc;
}

/* ---- figures ---------------------------------------------------------- */

double flip_mean(const float *map, const float *mask, size_t count)
{
    double sum = 0.0;
    size_t inside = 0;
    for (size_t i = 0; i < count; ++i)
        if (metrics_in_mask(mask, i))
            sum += map[i], ++inside;
    return inside ? sum / (double)inside : NAN;
}

static float maximum_inside(const float *v, const float *mask, size_t n)
{
    float m = -INFINITY;
    for (size_t i = 0; i < n; ++i)
        if (metrics_in_mask(mask, i) && v[i] > m)
            m = v[i];
    return m;
}

/* LDR-FLIP of the grey pair clamped to [0, 1]. */
static int grey_ldr(const float *reference, const float *test, int w, int h, const char *what, float *map,
                    gt_error *e)
{
    size_t n = (size_t)w * (size_t)h;
    float *clamped = malloc(sizeof *clamped * 2 * n);
    if (!clamped)
        return gt_error_set(e, what, "out of memory");
    for (size_t i = 0; i < n; ++i) {
        clamped[i] = fminf(1.0f, fmaxf(0.0f, reference[i]));
        clamped[n + i] = fminf(1.0f, fmaxf(0.0f, test[i]));
    }
    flip_image r = {w, h, {clamped, clamped, clamped}}, t = {w, h, {clamped + n, clamped + n, clamped + n}};
    int rc = flip_ldr(&r, &t, FLIP_DEFAULT_PPD, what, map, e);
    free(clamped);
    return rc;
}

int flip_grey(const float *reference, const float *test, const float *mask, int width, int height, const char *what,
              float *map, flip_result *out, gt_error *e)
{
    size_t n = (size_t)width * (size_t)height;
    memset(out, 0, sizeof *out);
    float *own = map ? NULL : malloc(sizeof *own * (n ? n : 1));
    float *m = map ? map : own;
    if (!m)
        return gt_error_set(e, what, "out of memory");
    flip_image r = {width, height, {reference, reference, reference}}, t = {width, height, {test, test, test}};
    out->hdr = maximum_inside(reference, mask, n) > 1.0f;
    int rc;
    if (out->hdr) {
        out->exposures = flip_exposure_range(&r, mask);
        rc = flip_hdr(&r, &t, out->exposures, FLIP_DEFAULT_PPD, what, m, e);
    } else
        rc = grey_ldr(reference, test, width, height, what, m, e);
    out->mean = rc == 0 ? flip_mean(m, mask, n) : NAN;
    free(own);
    return rc;
}
