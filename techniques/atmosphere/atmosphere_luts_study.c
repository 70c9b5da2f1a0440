#include "atmosphere/atmosphere_luts_study.h"

#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "core/files/atomic_file.h"
#include "core/progress.h"
#include "atmosphere/atmosphere_luts_writers.h"
#include "atmosphere/atmosphere_quality.h"

enum { GRID_BLENDS = 4 }; /* the talk's t axis: 0, 1/3, 2/3, 1 */

atmosphere_luts_request atmosphere_luts_default_request(study_quality quality)
{
    const atmosphere_quality *q = atmosphere_quality_of(quality);
    atmosphere_luts_request rq = {.points = q->points, .blend_count = q->blend_count,
                                  .uniform_refinement = q->uniform_refinement, .seed = 1, .sky_pixels = q->sky_pixels,
                                  .sky_refinement = q->sky_refinement};
    /* The centres of blend_count equal parts of t; a count past the array is
     * left for the study's check of the request to refuse. */
    for (int k = 0; k < rq.blend_count && k < ATMOSPHERE_STUDY_MAX_BLENDS; ++k)
        rq.blends[k] = (k + 0.5) / rq.blend_count;
    return rq;
}

int atmosphere_luts_row_decision(const atmosphere_luts_row *row)
{
    const atmosphere_error_stats *x = &row->error.total;
    double tolerance = fmax(ATMOSPHERE_TOLERANCE, row->error.quadrature.p95);
    return x->p95 + ATMOSPHERE_INTERVAL_Z * x->p95_se <= tolerance ? 1
           : x->p95 - ATMOSPHERE_INTERVAL_Z * x->p95_se > tolerance ? -1
                                                                    : 0;
}

int atmosphere_luts_row_suffices(const atmosphere_luts_row *row) { return atmosphere_luts_row_decision(row) > 0; }

static const atmosphere_lut_sizes NONE = {{1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}};

static int *table_sizes(atmosphere_lut_sizes *s, int table)
{
    return table == ATMOSPHERE_TABLE_INSCATTER ? s->inscatter : table == ATMOSPHERE_TABLE_SUN ? s->sun : s->sky;
}

/* A configuration: the talk's size of `table` with axis `axis` at n (axis -1:
 * the talk's; -2: every spatial axis doubled), the other tables minimal. */
static atmosphere_lut_sizes configuration(int table, int axis, int n)
{
    atmosphere_lut_sizes talk = atmosphere_lut_sizes_talk(), s = NONE;
    int *to = table_sizes(&s, table);
    memcpy(to, table_sizes(&talk, table), sizeof(int) * 4);
    if (axis >= 0)
        to[axis] = n;
    for (int a = 0; a < 3 && axis == -2; ++a)
        to[a] = to[a] > 1 ? 2 * to[a] : 1;
    return s;
}

static int add_row(atmosphere_luts_result *out, const atmosphere_solution *solutions, int count,
                   const atmosphere_lut_reference *ref, int table, int axis, int n, int threads, gt_error *e)
{
    static const char *const axes[4] = {"theta_s", "theta_v", "y", "t"};
    atmosphere_lut_sizes s = configuration(table, axis, n);
    atmosphere_luts luts;
    atmosphere_table_error errors[ATMOSPHERE_TABLES];
    char msg[256];
    if (out->row_count >= ATMOSPHERE_STUDY_MAX_ROWS)
        return gt_error_set(e, "atmosphere", "more than %d rows", ATMOSPHERE_STUDY_MAX_ROWS);
    if (atmosphere_luts_build_from(&luts, solutions, count, &s, threads, msg, sizeof msg) != 0)
        return gt_error_set(e, "atmosphere", "%s", msg);
    int rc = atmosphere_lut_errors(&luts, ref, errors) == 0 ? 0 : gt_error_set(e, "atmosphere", "out of memory");
    atmosphere_luts_row *row = &out->rows[out->row_count++];
    memcpy(row->sizes, table_sizes(&s, table), sizeof row->sizes);
    row->table = table, row->talk = axis == -1, row->error = errors[table];
    row->bytes = atmosphere_lut_bytes(table, row->sizes);
    if (axis == -1)
        snprintf(row->label, sizeof row->label, "talk");
    else if (axis == -2)
        snprintf(row->label, sizeof row->label, "all spatial axes x2");
    else
        snprintf(row->label, sizeof row->label, "%s %d", axes[axis], n);
    atmosphere_luts_free(&luts);
    return rc;
}

/* Per table: the talk's size, then one axis at a time. */
static int sweep(atmosphere_luts_result *out, const atmosphere_solution *solutions, int count,
                 const atmosphere_lut_reference *ref, int threads, gt_error *e)
{
    static const int inscatter[][2] = {{-1, 0}, {0, 4}, {0, 16}, {0, 32}, {1, 16}, {1, 32}, {1, 128},
                                       {2, 2},  {2, 4}, {2, 16}, {3, 2}};
    static const int light[][2] = {{-1, 0}, {0, 16}, {0, 32}, {0, 128}, {2, 2}, {2, 4}, {2, 8}};
    int rc = 0;
    for (size_t k = 0; k < sizeof inscatter / sizeof *inscatter && rc == 0; ++k)
        rc = add_row(out, solutions, count, ref, ATMOSPHERE_TABLE_INSCATTER, inscatter[k][0], inscatter[k][1], threads, e);
    if (rc == 0 && out->request.uniform_refinement)
        rc = add_row(out, solutions, count, ref, ATMOSPHERE_TABLE_INSCATTER, -2, 0, threads, e);
    for (int table = ATMOSPHERE_TABLE_SUN; table <= ATMOSPHERE_TABLE_SKY; ++table)
        for (size_t k = 0; k < sizeof light / sizeof *light && rc == 0; ++k)
            rc = add_row(out, solutions, count, ref, table, light[k][0], light[k][1], threads, e);
    return rc;
}

static void find_rows(atmosphere_luts_result *out)
{
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table) {
        out->smallest_within[table] = out->talk_row[table] = -1;
        for (int k = 0; k < out->row_count; ++k) {
            const atmosphere_luts_row *row = &out->rows[k];
            int best = out->smallest_within[table];
            if (row->table != table)
                continue;
            if (row->talk)
                out->talk_row[table] = k;
            if (atmosphere_luts_row_suffices(row) && (best < 0 || row->bytes < out->rows[best].bytes))
                out->smallest_within[table] = k;
        }
    }
}

/* One line per row: table, bytes, interpolation p95 and max, quadrature p95, total p95, label. */
static int write_size_data(const char *dir, const atmosphere_luts_result *r, gt_error *e)
{
    char path[4096], text[8192];
    size_t len = (size_t)snprintf(text, sizeof text, "# table bytes interp_p95 interp_max quad_p95 total_p95 label\n");
    for (int k = 0; k < r->row_count; ++k) {
        const atmosphere_luts_row *x = &r->rows[k];
        len += (size_t)snprintf(text + len, sizeof text - len, "%d %.0f %.6e %.6e %.6e %.6e \"%s\"\n", x->table,
                                x->bytes, x->error.interpolation.p95, x->error.interpolation.max,
                                x->error.quadrature.p95, x->error.total.p95, x->label);
    }
    snprintf(path, sizeof path, "%s/atmosphere_sizes.dat", dir);
    return atomic_write_text(path, text, e);
}

static int solve_all(atmosphere_solution *solutions, const double *blends, int count, int threads, gt_error *e)
{
    atmosphere_model m = atmosphere_model_default();
    for (int k = 0; k < count; ++k)
        if (atmosphere_solve(&m, blends[k], threads, &solutions[k]) != 0) {
            for (int j = 0; j < k; ++j)
                atmosphere_solution_free(&solutions[j]);
            return gt_error_set(e, "atmosphere", "out of memory");
        }
    return 0;
}

/* The set of `kind` at `sizes` from the solutions into dir: every format
 * (linear) or the EXRs (the others: the shaders' lookup is linear). */
static int write_set(const char *dir, const atmosphere_solution *solutions, int count,
                     const atmosphere_lut_sizes *sizes, atmosphere_lut_parametrization kind, int threads,
                     atmosphere_luts *luts, gt_error *e)
{
    char msg[256];
    if (atmosphere_luts_build_parametrized(luts, solutions, count, sizes, kind, threads, msg, sizeof msg) != 0)
        return gt_error_set(e, "atmosphere", "%s", msg);
    int rc = kind == ATMOSPHERE_PARAM_LINEAR ? atmosphere_luts_write_all(dir, luts, e)
                                             : atmosphere_luts_write_exr(dir, luts, e);
    if (rc != 0)
        atmosphere_luts_free(luts);
    return rc;
}

int atmosphere_luts_write_tables(const char *dir, const atmosphere_lut_sizes *sizes,
                                 atmosphere_lut_parametrization kind, int threads, double *build_seconds, gt_error *e)
{
    atmosphere_lut_sizes talk = atmosphere_lut_sizes_talk();
    double blends[3 * ATMOSPHERE_LUT_MAX_AXIS];
    char msg[256];
    sizes = sizes ? sizes : &talk;
    if (atmosphere_lut_sizes_check(sizes, msg, sizeof msg) != 0 ||
        atmosphere_lut_parametrization_check(kind, sizes->inscatter, msg, sizeof msg) != 0)
        return gt_error_set(e, "atmosphere", "%s", msg);
    int count = atmosphere_lut_blends(sizes, blends);
    atmosphere_solution *solutions = malloc(sizeof *solutions * (size_t)count);
    double start = seconds_now();
    if (!solutions)
        return gt_error_set(e, "atmosphere", "out of memory");
    int rc = solve_all(solutions, blends, count, threads, e);
    atmosphere_luts luts;
    if (rc == 0) {
        rc = write_set(dir, solutions, count, sizes, kind, threads, &luts, e);
        for (int k = 0; k < count; ++k)
            atmosphere_solution_free(&solutions[k]);
    }
    free(solutions);
    if (rc == 0)
        atmosphere_luts_free(&luts);
    if (build_seconds)
        *build_seconds = seconds_now() - start;
    return rc;
}

/* The files of the set just written into dir (below the output folder as `sub`), for the report. */
static void list_files(atmosphere_luts_result *out, const char *sub, atmosphere_lut_parametrization kind,
                       const atmosphere_lut_sizes *sizes)
{
    static const char *const TEXT[] = {"atmosphere_luts.h", "atmosphere_luts.hlsl", "atmosphere_luts.glsl"};
    atmosphere_luts_file_set *set = &out->file_sets[out->file_set_count++];
    char name[128];
    set->parametrization = kind, set->sizes = *sizes, set->count = 0;
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table) {
        atmosphere_luts_exr_name(kind, table, name, sizeof name);
        snprintf(set->files[set->count++], sizeof set->files[0], "%s/%s", sub, name);
    }
    for (int k = 0; k < 3 && kind == ATMOSPHERE_PARAM_LINEAR; ++k)
        snprintf(set->files[set->count++], sizeof set->files[0], "%s/%s", sub, TEXT[k]);
}

/* The talk-size sets from the grid blends' solutions (solved since `start`:
 * the linear set's build time counts them) into dir, `sub` below the output
 * folder: the linear one in every format, Yusov 2013's (the talk's) and
 * Bruneton & Neyret's as EXR; in production also Yusov's at 4x the talk's
 * in-scatter size on every spatial axis (the sky table's x4 row) in dir/x4. */
static int write_talk_tables(const study_context *ctx, const atmosphere_solution *solutions, double start,
                             atmosphere_luts_result *out, gt_error *e)
{
    static const char sub[] = ATMOSPHERE_LUTS_DIR "/atmosphere", x4_sub[] = ATMOSPHERE_LUTS_DIR "/atmosphere/x4";
    atmosphere_lut_sizes talk = atmosphere_lut_sizes_talk(), x4 = talk;
    atmosphere_luts luts;
    char dir[2048], x4_dir[2048];
    int rc = study_make_dir(ctx, sub, dir, sizeof dir, e), threads = ctx->threads;
    for (int k = 0; k < ATMOSPHERE_PARAMS && rc == 0; ++k) {
        rc = write_set(dir, solutions, GRID_BLENDS, &talk, (atmosphere_lut_parametrization)k, threads, &luts, e);
        if (rc == 0 && k == ATMOSPHERE_PARAM_LINEAR)
            out->build_seconds = seconds_now() - start;
        if (rc == 0)
            atmosphere_luts_free(&luts), list_files(out, sub, (atmosphere_lut_parametrization)k, &talk);
    }
    if (rc != 0 || !out->request.sky_refinement)
        return rc;
    for (int a = 0; a < 3; ++a)
        x4.inscatter[a] *= 4;
    if (study_make_dir(ctx, x4_sub, x4_dir, sizeof x4_dir, e) != 0)
        return -1;
    rc = write_set(x4_dir, solutions, GRID_BLENDS, &x4, ATMOSPHERE_PARAM_YUSOV, threads, &luts, e);
    if (rc == 0)
        atmosphere_luts_free(&luts), list_files(out, x4_sub, ATMOSPHERE_PARAM_YUSOV, &x4);
    return rc;
}

/* The sky through the in-scatter table of `kind` with axis `axis` at n (-1:
 * the talk's size; -2: every spatial axis x4). */
static int add_sky_row(atmosphere_luts_result *out, const atmosphere_solution *solutions, int count,
                       const atmosphere_sky_sample sample[2], atmosphere_lut_parametrization kind, int axis, int n,
                       int threads, gt_error *e)
{
    static const char *const axes[4] = {"theta_s", "theta_v", "y", "t"};
    atmosphere_lut_sizes s = configuration(ATMOSPHERE_TABLE_INSCATTER, axis == -2 ? -1 : axis, n);
    for (int a = 0; a < 3 && axis == -2; ++a)
        s.inscatter[a] *= 4;
    atmosphere_luts luts;
    char msg[256];
    if (out->sky_row_count >= ATMOSPHERE_SKY_MAX_ROWS)
        return gt_error_set(e, "atmosphere", "more than %d sky rows", ATMOSPHERE_SKY_MAX_ROWS);
    if (atmosphere_luts_build_parametrized(&luts, solutions, count, &s, kind, threads, msg, sizeof msg) != 0)
        return gt_error_set(e, "atmosphere", "%s", msg);
    atmosphere_sky_row *row = &out->sky_rows[out->sky_row_count++];
    int rc = atmosphere_sky_errors(&luts, &sample[0], &row->day) == 0 &&
                     atmosphere_sky_errors(&luts, &sample[1], &row->twilight) == 0
                 ? 0
                 : gt_error_set(e, "atmosphere", "out of memory");
    memcpy(row->sizes, s.inscatter, sizeof row->sizes);
    row->parametrization = kind, row->talk = axis == -1;
    row->bytes = atmosphere_lut_bytes(ATMOSPHERE_TABLE_INSCATTER, row->sizes);
    if (axis == -1)
        snprintf(row->label, sizeof row->label, "talk");
    else if (axis == -2)
        snprintf(row->label, sizeof row->label, "all spatial axes x4");
    else
        snprintf(row->label, sizeof row->label, "%s %d", axes[axis], n);
    if (axis == -1)
        out->sky_talk_row[kind] = out->sky_row_count - 1;
    atmosphere_luts_free(&luts);
    return rc;
}

/* Per parametrization: the talk's size, one axis at a time, and (production) x4. */
static int sky_sweep(atmosphere_luts_result *out, const atmosphere_solution *solutions, int count, int threads,
                     gt_error *e)
{
    static const int steps[][2] = {{-1, 0}, {0, 4}, {0, 16}, {0, 32}, {1, 32}, {1, 128}, {2, 4}, {2, 16}};
    const atmosphere_luts_request *rq = &out->request;
    atmosphere_sky_sample sample[2];
    const atmosphere_solution *off_grid = solutions + GRID_BLENDS;
    for (int k = 0; k < ATMOSPHERE_PARAMS; ++k)
        out->sky_talk_row[k] = -1;
    if (atmosphere_sky_sample_build(&sample[0], off_grid, rq->blend_count, rq->sky_pixels, 0.0, ATMOSPHERE_DAY_THETA_S,
                                    rq->seed, threads) != 0)
        return gt_error_set(e, "atmosphere", "out of memory");
    if (atmosphere_sky_sample_build(&sample[1], off_grid, rq->blend_count, rq->sky_pixels, ATMOSPHERE_DAY_THETA_S,
                                    ATMOSPHERE_TWILIGHT_THETA_S, rq->seed + 1u, threads) != 0) {
        atmosphere_sky_sample_free(&sample[0]);
        return gt_error_set(e, "atmosphere", "out of memory");
    }
    int rc = 0;
    for (int k = 0; k < ATMOSPHERE_PARAMS && rc == 0; ++k) {
        for (size_t j = 0; j < sizeof steps / sizeof *steps && rc == 0; ++j)
            rc = add_sky_row(out, solutions, count, sample, (atmosphere_lut_parametrization)k, steps[j][0],
                             steps[j][1], threads, e);
        if (rc == 0 && rq->sky_refinement)
            rc = add_sky_row(out, solutions, count, sample, (atmosphere_lut_parametrization)k, -2, 0, threads, e);
    }
    atmosphere_sky_sample_free(&sample[0]), atmosphere_sky_sample_free(&sample[1]);
    return rc;
}

static int run(const study_context *ctx, atmosphere_luts_result *out, const atmosphere_solution *solutions, int count,
               gt_error *e)
{
    atmosphere_lut_reference ref;
    const atmosphere_luts_request *rq = &out->request;
    if (atmosphere_lut_reference_build(&ref, solutions + GRID_BLENDS, rq->blend_count, rq->points, rq->seed,
                                       ctx->threads) != 0)
        return gt_error_set(e, "atmosphere", "out of memory");
    out->quadrature_estimate = ref.quadrature_estimate;
    int rc = sweep(out, solutions, count, &ref, ctx->threads, e);
    atmosphere_lut_reference_free(&ref);
    if (rc == 0)
        rc = sky_sweep(out, solutions, count, ctx->threads, e);
    find_rows(out);
    return rc;
}

int atmosphere_luts_study(const study_context *ctx, const atmosphere_luts_request *rq, atmosphere_luts_result *out,
                          gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->request = *rq;
    if (rq->blend_count < 1 || rq->blend_count > ATMOSPHERE_STUDY_MAX_BLENDS || rq->points < 20 || rq->sky_pixels < 20)
        return gt_error_set(e, "atmosphere", "1 to %d blends and at least 20 points and sky pixels",
                            ATMOSPHERE_STUDY_MAX_BLENDS);
    char dir[2048];
    if (study_make_dir(ctx, ATMOSPHERE_LUTS_DIR, dir, sizeof dir, e) != 0)
        return -1;
    double blends[GRID_BLENDS + ATMOSPHERE_STUDY_MAX_BLENDS] = {0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0};
    int count = GRID_BLENDS + rq->blend_count;
    memcpy(blends + GRID_BLENDS, rq->blends, sizeof(double) * (size_t)rq->blend_count);
    atmosphere_solution solutions[GRID_BLENDS + ATMOSPHERE_STUDY_MAX_BLENDS];
    double start = seconds_now();
    if (solve_all(solutions, blends, GRID_BLENDS, ctx->threads, e) != 0)
        return -1;
    int rc = write_talk_tables(ctx, solutions, start, out, e);
    if (rc != 0)
        count = GRID_BLENDS;
    else if (solve_all(solutions + GRID_BLENDS, blends + GRID_BLENDS, rq->blend_count, ctx->threads, e) != 0)
        count = GRID_BLENDS, rc = -1;
    if (rc == 0)
        rc = run(ctx, out, solutions, count, e);
    for (int k = 0; k < count; ++k)
        atmosphere_solution_free(&solutions[k]);
    return rc == 0 ? write_size_data(dir, out, e) : rc;
}
