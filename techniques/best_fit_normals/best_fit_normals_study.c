/* The best-fit normals study (best_fit_normals/best_fit_normals_study.h). */
#include "best_fit_normals/best_fit_normals_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/atomic_file.h"
#include "core/frame.h"
#include "core/optics/ggx.h"
#include "core/files/image_io.h"
#include "core/progress.h"
#include "best_fit_normals/best_fit_normals.h"
#include "best_fit_normals/best_fit_normals_cells.h"
#include "best_fit_normals/best_fit_normals_quality.h"
#include "best_fit_normals/best_fit_normals_writers.h"
#include "metrics/ssim.h"
#include "best_fit_normals/normal_encoding.h"

enum { EXHAUSTIVE = 4, OCTAHEDRAL = 5 };
static const char *const encoding_names[NORMALS_ENCODINGS] = {
    "RGB8 normalised",        "RGB8 / max component",   "RGB8 best fit (table, point)",
    "RGB8 best fit (table, bilinear)", "RGB8 best cell (exhaustive)", "octahedral 2x8",
    "octahedral 2x8 precise", "octahedral 2x10",        "octahedral 2x10 precise",
    "octahedral 2x12",        "octahedral 2x12 precise"};
static const int encoding_bits[NORMALS_ENCODINGS] = {24, 24, 24, 24, 24, 16, 16, 20, 20, 24, 24};
static const double roughnesses[NORMALS_ROUGHNESSES] = {0.1, 0.2, 0.3, 0.5};

normals_request normals_default_request(study_quality quality)
{
    const best_fit_normals_quality *q = best_fit_normals_quality_of(quality);
    normals_request rq = {.table_size = BFN_TALK_SIZE, .directions = q->directions,
                          .exhaustive_directions = q->exhaustive_directions, .face_count = q->face_count,
                          .seed = 2010u};
    static const int faces[] = {512, 1024, 2048, 4096, 8192};
    memcpy(rq.faces, faces, sizeof faces);
    return rq;
}

float *normals_write_table(const char *dir, int size, int threads, double *seconds, gt_error *e)
{
    double start = seconds_now();
    float *table = bfn_table_build(size, BFN_ERROR_PUBLISHED, threads);
    *seconds = seconds_now() - start;
    if (!table)
        return gt_error_set(e, dir, "out of memory"), NULL;
    char base[64], description[256];
    snprintf(base, sizeof base, "best_fit_normals_%d", size);
    snprintf(description, sizeof description,
             "best-fit normals (Kaplanyan 2010, Appendix A): scale t per texel, u = larger minor |n_i|, "
             "v = smaller / larger, %dx%d, the talk's error metric", size, size);
    if (bfn_table_write_all(dir, base, table, size, description, e) != 0) {
        free(table);
        return NULL;
    }
    return table;
}

/* A uniformly distributed unit direction from the index alone (so any
 * thread computes the same one): two SplitMix64 draws. */
static double hash_uniform(unsigned long long x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return (double)((x ^ (x >> 31)) >> 11) * 0x1.0p-53;
}

static void random_direction(unsigned seed, int i, double n[3])
{
    unsigned long long k = ((unsigned long long)seed << 32) ^ (unsigned long long)i * 2ull;
    double z = 2.0 * hash_uniform(k) - 1.0, phi = 2.0 * M_PI * hash_uniform(k + 1), r = sqrt(fmax(0.0, 1.0 - z * z));
    n[0] = r * cos(phi), n[1] = r * sin(phi), n[2] = z;
}

/* n through encoding `enc` and back. */
static void round_trip(int enc, const best_fit_table *t, const double n[3], double out[3])
{
    if (enc < EXHAUSTIVE) {
        int code[3];
        rgb8_encode((rgb8_encoding)enc, t, n, code);
        rgb8_decode(code, out);
    } else if (enc == EXHAUSTIVE) {
        bfn_best_cell_exhaustive(n, out);
        double l = sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
        out[0] /= l, out[1] /= l, out[2] /= l;
    } else {
        int bits = 8 + 2 * ((enc - OCTAHEDRAL) / 2), code[2];
        octahedral_encode(n, bits, (enc - OCTAHEDRAL) % 2, code);
        octahedral_decode(code, bits, out);
    }
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Mean, 99th percentile (nearest rank) and maximum of n errors, in degrees. */
static void error_statistics(double *err, int n, normals_encoding_result *r)
{
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        sum += err[i];
    qsort(err, (size_t)n, sizeof *err, compare_double);
    int rank = (int)ceil(0.99 * n);
    r->directions = n;
    r->mean_deg = sum / n * 180.0 / M_PI;
    r->p99_deg = err[rank - 1] * 180.0 / M_PI;
    r->max_deg = err[n - 1] * 180.0 / M_PI;
}

static void score_encoding(int enc, const best_fit_table *t, const normals_request *rq, int threads, double *err,
                           normals_encoding_result *r, double percentiles[101])
{
    int n = enc == EXHAUSTIVE ? rq->exhaustive_directions : rq->directions;
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int i = 0; i < n; ++i) {
        double d[3], q[3];
        random_direction(rq->seed, i, d);
        round_trip(enc, t, d, q);
        err[i] = bfn_angle(q, d);
    }
    r->name = encoding_names[enc];
    r->bits = encoding_bits[enc];
    error_statistics(err, n, r);
    for (int p = 0; p <= 100; ++p) /* sorted by error_statistics */
        percentiles[p] = err[p == 0 ? 0 : (int)ceil(p / 100.0 * n) - 1] * 180.0 / M_PI;
}

/* normals/error_cdf.dat: per percentile (rows), each encoding's error in
 * degrees (columns, in the order of the result): the plot's data. */
static int write_cdf(const char *dir, double percentiles[NORMALS_ENCODINGS][101], gt_error *e)
{
    char path[4096 + 32];
    snprintf(path, sizeof path, "%s/error_cdf.dat", dir);
    atomic_file file;
    FILE *f = atomic_file_open(&file, path, "w", e);
    if (!f)
        return -1;
    fprintf(f, "# percentile, then the angular error (degrees) of each encoding\n");
    for (int p = 0; p <= 100; ++p) {
        fprintf(f, "%d", p);
        for (int enc = 0; enc < NORMALS_ENCODINGS; ++enc)
            fprintf(f, " %.6e", percentiles[enc][p]);
        fputc('\n', f);
    }
    return atomic_file_close(&file, f, e);
}

/* The fixed generic rotation of the highlight's normals: angle 0.7 about
 * (1, 2, 3) / sqrt(14) (Rodrigues' formula); `inverse` turns back. */
static void rotate(const double in[3], int inverse, double out[3])
{
    double k[3] = {1.0 / sqrt(14.0), 2.0 / sqrt(14.0), 3.0 / sqrt(14.0)}, a = inverse ? -0.7 : 0.7;
    double c = cos(a), s = sin(a), kv = k[0] * in[0] + k[1] * in[1] + k[2] * in[2];
    double cross[3] = {k[1] * in[2] - k[2] * in[1], k[2] * in[0] - k[0] * in[2], k[0] * in[1] - k[1] * in[0]};
    for (int i = 0; i < 3; ++i)
        out[i] = in[i] * c + cross[i] * s + k[i] * kv * (1.0 - c);
}

/* The curved surface's normal at pixel (x, y): tilted up to 6 degrees. */
static void surface_normal(int x, int y, double n[3])
{
    double k = tan(6.0 * M_PI / 180.0), size = NORMALS_HIGHLIGHT_SIZE;
    double px = (2.0 * (x + 0.5) / size - 1.0) * k, py = (2.0 * (y + 0.5) / size - 1.0) * k, l = sqrt(1 + px * px + py * py);
    n[0] = -px / l, n[1] = -py / l, n[2] = 1.0 / l;
}

/* f_GGX(v, l) n.l with v = l = +z (the mirror direction of the axis). */
static double shade(const double n[3], double alpha)
{
    frame f = frame_from_normal(v3((float)n[0], (float)n[1], (float)n[2]));
    vec3 w = frame_to_local(&f, v3(0.0f, 0.0f, 1.0f));
    return ggx_brdf(w, w, alpha) * w.z;
}

/* The surface's normals through encoding enc (-1: exact), 3 floats a pixel. */
static void decode_normals(int enc, const best_fit_table *t, int threads, float *normals)
{
    const int size = NORMALS_HIGHLIGHT_SIZE;
#pragma omp parallel for schedule(dynamic, 8) num_threads(threads)
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            double n[3], w[3], q[3];
            surface_normal(x, y, n);
            if (enc >= 0) {
                rotate(n, 0, w);
                round_trip(enc, t, w, q);
                rotate(q, 1, n);
            }
            for (int c = 0; c < 3; ++c)
                normals[3 * (y * size + x) + c] = (float)n[c];
        }
}

/* Radiance of the surface with the given normals. */
static void render_highlight(const float *normals, double alpha, int threads, float *out)
{
    const int pixels = NORMALS_HIGHLIGHT_SIZE * NORMALS_HIGHLIGHT_SIZE;
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int i = 0; i < pixels; ++i) {
        double n[3] = {normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]};
        out[i] = (float)shade(n, alpha);
    }
}

/* x / (1 + x) after scaling so the exact image's peak is 4. */
static void tone_map(float *img, double peak)
{
    for (int i = 0; i < NORMALS_HIGHLIGHT_SIZE * NORMALS_HIGHLIGHT_SIZE; ++i) {
        double x = img[i] * 4.0 / peak;
        img[i] = (float)(x / (1.0 + x));
    }
}

static double peak_of(const float *img)
{
    double m = 0.0;
    for (int i = 0; i < NORMALS_HIGHLIGHT_SIZE * NORMALS_HIGHLIGHT_SIZE; ++i)
        m = fmax(m, img[i]);
    return m;
}

/* The previews of the report's figure: roughness 0.2, four encodings. */
static int write_preview(const char *dir, int enc, const float *img, gt_error *e)
{
    static const char *const names[NORMALS_ENCODINGS] = {[0] = "naive", [2] = "best_fit", [8] = "octahedral10p"};
    if (enc >= 0 && !names[enc])
        return 0;
    char path[4096 + 64];
    snprintf(path, sizeof path, "%s/highlight_%s.png", dir, enc < 0 ? "exact" : names[enc]);
    const float *planes[1] = {img};
    return image_write_preview(path, planes, 1, NORMALS_HIGHLIGHT_SIZE, NORMALS_HIGHLIGHT_SIZE, 1.0f, e);
}

/* The exact image of roughness r, tone-mapped, and its peak radiance. */
static double exact_highlight(const float *normals, int r, int threads, float *out)
{
    render_highlight(normals, ggx_alpha(roughnesses[r]), threads, out);
    double peak = peak_of(out);
    tone_map(out, peak);
    return peak;
}

static int score_encoding_highlights(const char *dir, int enc, const float *exact_normals, const float *normals,
                                     int threads, float *exact, float *img, normals_result *out, gt_error *e)
{
    int rc = 0;
    for (int r = 0; r < NORMALS_ROUGHNESSES && rc == 0; ++r) {
        double peak = exact_highlight(exact_normals, r, threads, exact);
        render_highlight(normals, ggx_alpha(roughnesses[r]), threads, img);
        tone_map(img, peak);
        ssim_result s;
        rc = ssim_compute(exact, img, NULL, NORMALS_HIGHLIGHT_SIZE, NORMALS_HIGHLIGHT_SIZE, "normals highlight", NULL,
                          &s, e);
        out->encodings[enc].highlight_dssim[r] = s.dssim;
        if (rc == 0 && r == 1)
            rc = write_preview(dir, enc, img, e);
    }
    return rc;
}

/* Each encoding's normals once, then its image at every roughness. */
static int score_highlights(const char *dir, const best_fit_table *t, int threads, normals_result *out, gt_error *e)
{
    size_t pixels = (size_t)NORMALS_HIGHLIGHT_SIZE * NORMALS_HIGHLIGHT_SIZE;
    float *exact = malloc(pixels * sizeof *exact), *img = malloc(pixels * sizeof *img);
    float *exact_normals = malloc(3 * pixels * sizeof *exact_normals), *normals = malloc(3 * pixels * sizeof *normals);
    int rc = exact && img && exact_normals && normals ? 0 : gt_error_set(e, "normals highlight", "out of memory");
    if (rc == 0) {
        decode_normals(-1, t, threads, exact_normals);
        exact_highlight(exact_normals, 1, threads, exact);
        rc = write_preview(dir, -1, exact, e);
    }
    for (int r = 0; r < NORMALS_ROUGHNESSES; ++r)
        out->roughness[r] = roughnesses[r];
    for (int enc = 0; enc < NORMALS_ENCODINGS && rc == 0; ++enc) {
        decode_normals(enc, t, threads, normals);
        rc = score_encoding_highlights(dir, enc, exact_normals, normals, threads, exact, img, out, e);
    }
    free(exact), free(img), free(exact_normals), free(normals);
    return rc;
}

static int count_cells(const char *dir, const normals_request *rq, int threads, normals_result *out, gt_error *e)
{
    out->cells_sphere = bfn_cells_sphere();
    out->cells_surface = bfn_cells_surface();
    out->cells_distinct = bfn_cells_distinct(threads);
    char path[4096 + 16];
    snprintf(path, sizeof path, "%s/cells.dat", dir);
    atomic_file file;
    FILE *f = atomic_file_open(&file, path, "w", e);
    if (!f)
        return -1;
    fprintf(f, "# face  naive%%  max%%  best_fit%%  (sampled cells / 256^3)\n");
    for (int i = 0; i < rq->face_count; ++i) {
        normals_cells_row *row = &out->sampled[i];
        row->face = rq->faces[i];
        row->naive = bfn_cells_sampled(BFN_SAMPLED_NAIVE, row->face, threads);
        row->max = bfn_cells_sampled(BFN_SAMPLED_MAX, row->face, threads);
        row->best_fit = bfn_cells_sampled(BFN_SAMPLED_BEST_FIT, row->face, threads);
        fprintf(f, "%d %.6f %.6f %.6f\n", row->face, 100.0 * row->naive / BFN_CELL_COUNT,
                100.0 * row->max / BFN_CELL_COUNT, 100.0 * row->best_fit / BFN_CELL_COUNT);
    }
    return atomic_file_close(&file, f, e);
}

int normals_study(const study_context *ctx, const normals_request *rq, normals_result *out, gt_error *e)
{
    char dir[4096];
    memset(out, 0, sizeof *out);
    out->request = *rq;
    if (study_make_dir(ctx, NORMALS_DIR, dir, sizeof dir, e) != 0)
        return -1;
    float *table = normals_write_table(dir, rq->table_size, ctx->threads, &out->table_seconds, e);
    double *err = malloc(sizeof *err * (size_t)rq->directions);
    int rc = table && err ? 0 : (table ? gt_error_set(e, dir, "out of memory") : -1);
    best_fit_table t = {table, rq->table_size};
    static double percentiles[NORMALS_ENCODINGS][101];
    for (int enc = 0; enc < NORMALS_ENCODINGS && rc == 0; ++enc)
        score_encoding(enc, &t, rq, ctx->threads, err, &out->encodings[enc], percentiles[enc]);
    if (rc == 0)
        rc = write_cdf(dir, percentiles, e);
    if (rc == 0)
        rc = score_highlights(dir, &t, ctx->threads, out, e);
    if (rc == 0)
        rc = count_cells(dir, rq, ctx->threads, out, e);
    free(err);
    free(table);
    return rc;
}
