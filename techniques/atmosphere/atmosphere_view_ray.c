/* The radiance along one view ray with the sun at its true azimuth
 * (atmosphere_scattering.h, atmosphere_view_radiance): single scattering
 * of both species and the solved higher orders, integrated together. */
#include <math.h>

#include "core/optics/phase_function.h"
#include "core/sampling/quadrature.h"
#include "atmosphere/atmosphere_scattering.h"
#include "atmosphere/atmosphere_scattering_parts.h"

enum { VIEW_COMPONENTS = (ATMOSPHERE_SPECIES + 1) * ATMOSPHERE_CHANNELS }; /* S_R, S_M, M */

typedef struct {
    const atmosphere_solution *s;
    atmosphere_method how;
    const atmosphere_view_ray *ray;
} view_problem;

/* values[3 i + c] = single_i,c; values[6 + c] = multiple_c. */
static void view_components_at(double dist, void *ctx, double *values)
{
    const view_problem *q = ctx;
    double single[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS];
    atmosphere_view_integrands(q->s, q->how, q->ray, dist, single, values + 6);
    for (int i = 0; i < ATMOSPHERE_SPECIES; ++i)
        for (int c = 0; c < 3; ++c)
            values[3 * i + c] = single[i][c];
}

double atmosphere_view_radiance(const atmosphere_solution *s, atmosphere_method how, const atmosphere_view_ray *ray,
                                double tol, double L[ATMOSPHERE_CHANNELS],
                                double S[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS], double M[ATMOSPHERE_CHANNELS])
{
    view_problem q = {s, how == ATMOSPHERE_FAST ? ATMOSPHERE_ADAPTIVE : how, ray};
    double breaks[ATMOSPHERE_RAY_BREAKS], scale[VIEW_COMPONENTS], abs_tol[VIEW_COMPONENTS];
    double value[VIEW_COMPONENTS], error[VIEW_COMPONENTS], worst = 0.0;
    atmosphere_ray_breaks(ray->length, breaks);
    for (int k = 0; k < VIEW_COMPONENTS; ++k) {
        scale[k] = atmosphere_single_scale(s, k < 6 ? k / 3 : ATMOSPHERE_RAYLEIGH, k % 3);
        abs_tol[k] = tol * scale[k];
    }
    quadrature_gk15_vector_split(view_components_at, &q, VIEW_COMPONENTS, breaks, ATMOSPHERE_RAY_BREAKS, abs_tol,
                                 value, error);
    double pr = rayleigh_phase(ray->nu), pm = cornette_shanks_phase(ray->nu, s->model.mie_g);
    for (int c = 0; c < 3; ++c) {
        L[c] = pr * value[c] + pm * value[3 + c] + value[6 + c];
        for (int i = 0; S && i < ATMOSPHERE_SPECIES; ++i)
            S[i][c] = value[3 * i + c];
        if (M)
            M[c] = value[6 + c];
    }
    for (int k = 0; k < VIEW_COMPONENTS; ++k)
        worst = fmax(worst, scale[k] > 0.0 ? error[k] / scale[k] : 0.0);
    return worst;
}
