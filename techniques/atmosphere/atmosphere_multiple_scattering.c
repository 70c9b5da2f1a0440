/* Multiple scattering of atmosphere_scattering.h: the azimuthally averaged
 * phases, their cell kernels, the orders (Bruneton 2017,
 * ComputeScatteringDensity -> ComputeMultipleScattering, azimuth-averaged),
 * and the solution's precomputation (the transmittance grid, then the
 * orders). */
#include <math.h>
#include <stdlib.h>

#include "core/optics/phase_function.h"
#include "core/sampling/quadrature.h"
#include "core/vec3.h" /* M_PI */
#include "atmosphere/atmosphere_scattering.h"
#include "atmosphere/atmosphere_scattering_parts.h"

enum { NR = ATMOSPHERE_MS_R, NMU = ATMOSPHERE_MS_MU, NS = ATMOSPHERE_MS_MU_S };
static const double CELL = 2.0 / NMU;

/* ---- Azimuthally averaged phases ------------------------------------- */

typedef struct {
    double g, ab, sab;
} azimuth_ctx;

static double mie_at_azimuth(double phi, void *ctx)
{
    const azimuth_ctx *q = ctx;
    return cornette_shanks_phase(q->ab + q->sab * cos(phi), q->g);
}

/* Rayleigh in closed form: the mean of c^2 over phi is (ab)^2 + sab^2 / 2. */
double atmosphere_azimuthal_phase(int species, double g, double mu_a, double mu_b)
{
    double ab = mu_a * mu_b, sab = sqrt(fmax(0.0, (1.0 - mu_a * mu_a) * (1.0 - mu_b * mu_b)));
    if (species == ATMOSPHERE_RAYLEIGH)
        return 3.0 / (16.0 * M_PI) * (1.0 + ab * ab + 0.5 * sab * sab);
    azimuth_ctx q = {g, ab, sab};
    return quadrature_gk15(mie_at_azimuth, &q, 0.0, M_PI, 1e-9, NULL) / M_PI;
}

typedef struct {
    int species;
    double g, mu_a;
} kernel_ctx;

static double kernel_at(double mu, void *ctx)
{
    const kernel_ctx *q = ctx;
    return atmosphere_azimuthal_phase(q->species, q->g, q->mu_a, mu);
}

/* 2 pi \int_{lo}^{hi} Pbar_i(mu_a, mu') dmu': the share of light scattered
 * from a direction of zenith cosine mu_a into the band [lo, hi]. */
static double band_share(int species, double g, double mu_a, double lo, double hi)
{
    kernel_ctx q = {species, g, mu_a};
    if (mu_a > lo && mu_a < hi) {
        double points[3] = {lo, mu_a, hi};
        return 2.0 * M_PI * quadrature_gk15_split(kernel_at, &q, points, 3, 1e-9, NULL);
    }
    return 2.0 * M_PI * quadrature_gk15(kernel_at, &q, lo, hi, 1e-9, NULL);
}

/* W[i][a][b]: cell b's share from direction mu_a (rows sum to 1); C[i][b][m]:
 * cell b's share from the sun at mu_s,m. */
static void fill_kernels(const atmosphere_model *m, double *W, double *C, int threads)
{
#pragma omp parallel for schedule(dynamic, 8) num_threads(threads)
    for (int q = 0; q < 2 * NMU * NMU; ++q) {
        int i = q / (NMU * NMU), a = q / NMU % NMU, b = q % NMU;
        double lo = -1.0 + b * CELL;
        W[q] = band_share(i, m->mie_g, atmosphere_ms_mu(a), lo, lo + CELL);
    }
#pragma omp parallel for schedule(dynamic, 8) num_threads(threads)
    for (int q = 0; q < 2 * NMU * NS; ++q) {
        int i = q / (NMU * NS), b = q / NS % NMU, mm = q % NS;
        double lo = -1.0 + b * CELL;
        C[q] = band_share(i, m->mie_g, atmosphere_ms_mu_s(mm), lo, lo + CELL);
    }
}

/* ---- The orders ------------------------------------------------------- */

/* L^1 (the radiance seen from cell b, phase-weighted single scattering, per
 * unit solid angle: C / (2 pi dmu)) at every grid point. */
static void first_order(atmosphere_solution *s, const double *C, double *L, int threads)
{
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
    for (int q = 0; q < NR * NMU * NS; ++q) {
        int k = q / (NMU * NS), b = q / NS % NMU, mm = q % NS;
        double S[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS];
        atmosphere_single_scattering(s, ATMOSPHERE_FAST, atmosphere_ms_radius(&s->model, k), atmosphere_ms_mu(b),
                                     atmosphere_ms_mu_s(mm), 0.0, S);
        for (int c = 0; c < 3; ++c) {
            L[3 * q + c] = 0.0;
            for (int i = 0; i < ATMOSPHERE_SPECIES; ++i)
                L[3 * q + c] += C[(i * NMU + b) * NS + mm] / (2.0 * M_PI * CELL) * S[i][c];
        }
    }
}

/* J(r_k, mu_a, mu_s,m) = sum_j beta_s^j(r_k) sum_b W_j(a, b) L(r_k, mu_b, mu_s,m). */
static void density_from(const atmosphere_solution *s, const double *W, const double *L, double *J, int threads)
{
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int q = 0; q < NR * NMU * NS; ++q) {
        int k = q / (NMU * NS), a = q / NS % NMU, mm = q % NS;
        double r = atmosphere_ms_radius(&s->model, k);
        atmosphere_coefficients co = atmosphere_coefficients_at(&s->model, s->t, r - s->model.bottom_radius);
        for (int c = 0; c < 3; ++c) {
            double sum = 0.0;
            for (int j = 0; j < ATMOSPHERE_SPECIES; ++j)
                for (int b = 0; b < NMU; ++b)
                    sum += co.scattering[j][c] * W[(j * NMU + a) * NMU + b] * L[3 * atmosphere_ms_index(k, b, mm) + c];
            J[3 * q + c] = sum;
        }
    }
}

/* The fixed ray rule's nodes of every grid point's ray, computed once for
 * all orders: the weight times the transmittance from the grid point, and
 * where the node is, (r_s, mu, mu_s) (floats: 24 B a node). */
typedef struct {
    float wT[3], r, mu, mu_s;
} ray_node;

static void fill_ray_nodes(const atmosphere_solution *s, ray_node *nodes, int threads)
{
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
    for (int q = 0; q < NR * NMU * NS; ++q) {
        int k = q / (NMU * NS), a = q / NS % NMU, mm = q % NS;
        double r = atmosphere_ms_radius(&s->model, k), mu = atmosphere_ms_mu(a), mu_s = atmosphere_ms_mu_s(mm);
        double x[ATMOSPHERE_RAY_NODES], w[ATMOSPHERE_RAY_NODES];
        atmosphere_ray_rule(atmosphere_distance_to_boundary(&s->model, r, mu), x, w);
        for (int n = 0; n < ATMOSPHERE_RAY_NODES; ++n) {
            ray_node *node = nodes + (size_t)q * ATMOSPHERE_RAY_NODES + n;
            double r_s = atmosphere_radius_at(r, mu, x[n]), T[3];
            atmosphere_transmittance(s, ATMOSPHERE_FAST, r, mu, x[n], T);
            for (int c = 0; c < 3; ++c)
                node->wT[c] = (float)(w[n] * T[c]);
            node->r = (float)r_s;
            node->mu = (float)fmax(-1.0, fmin(1.0, (r * mu + x[n]) / r_s));
            node->mu_s = (float)fmax(-1.0, fmin(1.0, (r * mu_s + x[n] * mu * mu_s) / r_s));
        }
    }
}

/* L(q) = sum over q's ray nodes of wT J(node): the next order's radiance. */
static void next_order(const atmosphere_solution *s, const ray_node *nodes, const double *J, double *L, int threads)
{
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int q = 0; q < NR * NMU * NS; ++q) {
        double sum[3] = {0, 0, 0}, v[3];
        for (int n = 0; n < ATMOSPHERE_RAY_NODES; ++n) {
            const ray_node *node = nodes + (size_t)q * ATMOSPHERE_RAY_NODES + n;
            atmosphere_ms_lookup(&s->model, J, node->r, node->mu, node->mu_s, v);
            for (int c = 0; c < 3; ++c)
                sum[c] += node->wT[c] * v[c];
        }
        for (int c = 0; c < 3; ++c)
            L[3 * q + c] = sum[c];
    }
}

static double green_mean(const double *L)
{
    double sum = 0.0;
    for (int q = 0; q < NR * NMU * NS; ++q)
        sum += L[3 * q + 1];
    return sum / (NR * NMU * NS);
}

int atmosphere_multiple_scattering_solve(atmosphere_solution *s, int threads)
{
    size_t n = (size_t)NR * NMU * NS * 3;
    double *W = malloc(sizeof *W * 2 * NMU * NMU), *C = malloc(sizeof *C * 2 * NMU * NS);
    double *L = malloc(sizeof *L * n), *J = malloc(sizeof *J * n);
    ray_node *nodes = malloc(sizeof *nodes * (n / 3) * ATMOSPHERE_RAY_NODES);
    int rc = W && C && L && J && nodes ? 0 : -1;
    if (rc == 0) {
        fill_kernels(&s->model, W, C, threads);
        fill_ray_nodes(s, nodes, threads);
        first_order(s, C, L, threads);
        s->order_mean[1] = green_mean(L);
        for (int order = 2; order <= ATMOSPHERE_ORDERS; ++order) {
            density_from(s, W, L, J, threads);
            for (size_t q = 0; q < n; ++q)
                s->density[q] += J[q];
            next_order(s, nodes, J, L, threads);
            s->order_mean[order] = green_mean(L);
        }
    }
    free(W), free(C), free(L), free(J), free(nodes);
    return rc;
}

int atmosphere_solve(const atmosphere_model *m, double t, int threads, atmosphere_solution *s)
{
    size_t ms = (size_t)ATMOSPHERE_MS_R * ATMOSPHERE_MS_MU * ATMOSPHERE_MS_MU_S * 3;
    *s = (atmosphere_solution){.model = *m, .t = t};
    s->tau_top = malloc(sizeof *s->tau_top * ATMOSPHERE_T_R * ATMOSPHERE_T_MU * 3);
    s->density = calloc(ms, sizeof *s->density);
    if (!s->tau_top || !s->density) {
        atmosphere_solution_free(s);
        return -1;
    }
    atmosphere_transmittance_grid_fill(s, threads);
    if (atmosphere_multiple_scattering_solve(s, threads) != 0) {
        atmosphere_solution_free(s);
        return -1;
    }
    return 0;
}

void atmosphere_solution_free(atmosphere_solution *s)
{
    free(s->tau_top);
    free(s->density);
    s->tau_top = NULL, s->density = NULL;
}
