/* The GGX LTC fit (ltc/ltc_fit.h: the objective, the grid, the warm start). */
#include "ltc/ltc_fit.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>

#include "core/optics/ggx.h"
#include "core/sampling/hemisphere_sampling.h"
#include "fitters/ceres_bridge.h"
#include "luts/dfg_lut.h"

enum {
    BRDF_POINTS = LTC_FIT_BRDF_GRID * LTC_FIT_BRDF_GRID,
    COSINE_POINTS = LTC_FIT_COSINE_GRID * LTC_FIT_COSINE_GRID,
    GRID_POINTS = BRDF_POINTS + 2 * COSINE_POINTS
};

/* The quadrature: directions, sqrt of their weights, the normalised target. */
typedef struct {
    double l[GRID_POINTS][3], sqrt_w[GRID_POINTS], t[GRID_POINTS];
} ltc_grid;

/* Centre of cell k of a g x g grid of [0, 1)^2. */
static void grid_point(int k, int g, float u[2])
{
    u[0] = (float)((k % g + 0.5) / g), u[1] = (float)((k / g + 0.5) / g);
}

/* sum_k n_k p_k(l): the balance heuristic's denominator. */
static double mixture_density(vec3 v, double alpha, vec3 l)
{
    double cosine = fabs((double)l.z) / M_PI * COSINE_POINTS;
    return BRDF_POINTS * ggx_reflection_pdf(v, l, alpha) + cosine;
}

/* Direction k of the three grids (BRDF, upper cosine, lower cosine). */
static vec3 grid_direction(vec3 v, double alpha, int k)
{
    float u[2];
    if (k < BRDF_POINTS) {
        grid_point(k, LTC_FIT_BRDF_GRID, u);
        return ggx_reflect(v, ggx_sample_visible_normal(v, alpha, u));
    }
    k -= BRDF_POINTS;
    grid_point(k % COSINE_POINTS, LTC_FIT_COSINE_GRID, u);
    vec3 l = sample_cosine_hemisphere(u);
    return k < COSINE_POINTS ? l : v3(l.x, l.y, -l.z);
}

/* Fills the grid with target / norm and returns the grid's quadrature of
 * the target. */
static double build_grid(vec3 v, double alpha, ltc_target_fn target, void *user, double norm, ltc_grid *g)
{
    double sum = 0.0;
    for (int k = 0; k < GRID_POINTS; ++k) {
        vec3 l = v3_normalize(grid_direction(v, alpha, k));
        g->l[k][0] = l.x, g->l[k][1] = l.y, g->l[k][2] = l.z;
        double w = 1.0 / mixture_density(v, alpha, l);
        g->sqrt_w[k] = sqrt(w);
        g->t[k] = target(user, g->l[k]);
        sum += w * g->t[k];
    }
    for (int k = 0; k < GRID_POINTS; ++k)
        g->t[k] /= norm;
    return sum;
}

static int grid_residuals(void *user, const double *m, double *residuals, double *jacobian)
{
    const ltc_grid *g = user;
    (void)jacobian;
    for (int k = 0; k < GRID_POINTS; ++k)
        residuals[k] = g->sqrt_w[k] * (ltc_density(m, g->l[k]) - g->t[k]);
    return 0;
}

/* The total-variation distance and the quadrature of D. */
static void measure_fit(const ltc_grid *g, const double m[4], ltc_cell_fit *out)
{
    double tv = 0.0, integral = 0.0;
    for (int k = 0; k < GRID_POINTS; ++k) {
        double w = g->sqrt_w[k] * g->sqrt_w[k], d = ltc_density(m, g->l[k]);
        tv += 0.5 * w * fabs(d - g->t[k]), integral += w * d;
    }
    out->error = tv, out->integral = integral;
}

/* Ceres on the grid from m. */
static int solve_grid(ltc_grid *g, double m[4], ltc_cell_fit *out, gt_error *e)
{
    gt_fit *fit = gt_fit_create(4, m, e);
    if (!fit)
        return -1;
    gt_fit_block_options numeric = {GT_FIT_NUMERIC, GT_FIT_LOSS_NONE, 0.0};
    gt_fit_result r;
    int rc = gt_fit_set_bounds(fit, 0, 1e-6, 1e7, e) || gt_fit_set_bounds(fit, 2, 1e-6, 1e7, e) ||
             gt_fit_add_block(fit, GRID_POINTS, grid_residuals, g, &numeric, e) || gt_fit_solve(fit, NULL, &r, e);
    gt_fit_destroy(fit);
    if (rc)
        return -1;
    out->iterations = r.iterations;
    measure_fit(g, m, out);
    return 0;
}

int ltc_fit_cell_target(double n_dot_v, double alpha, ltc_target_fn target, void *user, double norm, double m[4],
                        ltc_cell_fit *out, gt_error *e)
{
    ltc_grid *g = malloc(sizeof *g);
    if (!g)
        return gt_error_set(e, "ltc fit", "out of memory");
    vec3 v = v3((float)sqrt(fmax(0.0, 1.0 - n_dot_v * n_dot_v)), 0.0f, (float)n_dot_v);
    out->albedo = build_grid(v, alpha, target, user, norm, g);
    int rc = solve_grid(g, m, out, e);
    free(g);
    return rc;
}

typedef struct {
    vec3 v;
    double alpha;
} ggx_target;

static double ggx_brdf_cosine(void *user, const double l[3])
{
    const ggx_target *t = user;
    vec3 lf = v3((float)l[0], (float)l[1], (float)l[2]);
    return l[2] > 0.0 ? ggx_brdf(t->v, lf, t->alpha) * l[2] : 0.0;
}

int ltc_fit_cell(double n_dot_v, double alpha, double albedo, double m[4], ltc_cell_fit *out, gt_error *e)
{
    ggx_target t = {v3((float)sqrt(fmax(0.0, 1.0 - n_dot_v * n_dot_v)), 0.0f, (float)n_dot_v), alpha};
    return ltc_fit_cell_target(n_dot_v, alpha, ggx_brdf_cosine, &t, albedo, m, out, e);
}

/* Texel (i, j): M^-1 fitted from m (updated), E and B by quadrature. */
static int fit_texel(ltc_table *t, int i, int j, double m[4], gt_error *e)
{
    double n_dot_v = ltc_n_dot_v_of_column(i, t->size), r = ltc_roughness_of_row(j, t->size), dfg[3];
    ltc_cell_fit f;
    dfg_integrate(n_dot_v, r, dfg);
    if (ltc_fit_cell(n_dot_v, ggx_alpha_tabulated(r), dfg[DFG_ALBEDO], m, &f, e) != 0)
        return -1;
    float *texel = t->data + ((size_t)j * t->size + i) * LTC_CHANNELS;
    for (int c = 0; c < 4; ++c)
        texel[c] = (float)m[c];
    texel[LTC_MAGNITUDE] = (float)dfg[DFG_ALBEDO], texel[LTC_FRESNEL] = (float)dfg[DFG_BIAS];
    t->error[(size_t)j * t->size + i] = (float)f.error;
    return 0;
}

void ltc_rotate_about_y(double m[4], double angle)
{
    double c = cos(angle), s = sin(angle), k = c - m[3] * s;
    if (!(k > 0.0))
        return;
    double a = (m[0] * c + m[1] * s) / k, b = (m[1] * c - m[0] * s) / k;
    m[0] = a, m[1] = b, m[2] /= k, m[3] = (m[3] * c + s) / k;
}

double ltc_ggx_lobe_axis(double n_dot_v, double alpha)
{
    ltc_grid *g = malloc(sizeof *g);
    if (!g)
        return 0.0;
    ggx_target t = {v3((float)sqrt(fmax(0.0, 1.0 - n_dot_v * n_dot_v)), 0.0f, (float)n_dot_v), alpha};
    build_grid(t.v, alpha, ggx_brdf_cosine, &t, 1.0, g);
    double x = 0.0, z = 0.0;
    for (int k = 0; k < GRID_POINTS; ++k)
        x += g->sqrt_w[k] * g->sqrt_w[k] * g->t[k] * g->l[k][0], z += g->sqrt_w[k] * g->sqrt_w[k] * g->t[k] * g->l[k][2];
    free(g);
    return atan2(x, z);
}

/* Row j from n.v ~ 1 to grazing: the first cell from the scaled cosine
 * turned to the lobe's axis, each next one from its neighbour's solution
 * turned by the axis' change. */
static int fit_row(ltc_table *t, int j, gt_error *e)
{
    double alpha = ggx_alpha_tabulated(ltc_roughness_of_row(j, t->size)), axis = 0.0;
    double m[4] = {1.0 / alpha, 0.0, 1.0 / alpha, 0.0};
    for (int i = 0; i < t->size; ++i) {
        double next = ltc_ggx_lobe_axis(ltc_n_dot_v_of_column(i, t->size), alpha);
        ltc_rotate_about_y(m, next - axis);
        axis = next;
        if (fit_texel(t, i, j, m, e) != 0)
            return -1;
    }
    return 0;
}

static void summarise_errors(ltc_table *t)
{
    size_t n = (size_t)t->size * t->size;
    t->max_error = t->mean_error = 0.0;
    for (size_t k = 0; k < n; ++k)
        t->max_error = fmax(t->max_error, t->error[k]), t->mean_error += t->error[k] / (double)n;
}

int ltc_fit_table(ltc_table *t, int size, int threads, gt_error *e)
{
    if (ltc_table_alloc(t, size) != 0)
        return gt_error_set(e, "ltc fit", "table size %d outside %d..%d or out of memory", size, LTC_MIN_SIZE,
                            LTC_MAX_SIZE);
    int failed_row = -1;
    gt_error row_error = {0};
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads > 0 ? threads : 1)
    for (int j = 0; j < size; ++j) {
        gt_error local = {0};
        if (fit_row(t, j, &local) != 0) {
#pragma omp critical(ltc_fit_failure)
            if (failed_row < 0 || j < failed_row)
                failed_row = j, row_error = local;
        }
    }
    if (failed_row >= 0) {
        ltc_table_free(t);
        if (e)
            *e = row_error;
        return -1;
    }
    summarise_errors(t);
    return 0;
}
