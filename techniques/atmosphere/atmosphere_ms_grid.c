/* The internal multiple-scattering grid of atmosphere_scattering.h
 * (ATMOSPHERE_MS_R x _MU x _MU_S over r, mu, mu_s): its coordinates and
 * its trilinear lookup, below both the single scattering (which reads the
 * solved orders along a view ray) and the multiple scattering that fills it. */
#include <math.h>
#include <stddef.h>

#include "atmosphere/atmosphere_scattering.h"
#include "atmosphere/atmosphere_scattering_parts.h"

enum { NR = ATMOSPHERE_MS_R, NMU = ATMOSPHERE_MS_MU, NS = ATMOSPHERE_MS_MU_S };
static const double CELL = 2.0 / NMU;

double atmosphere_ms_radius(const atmosphere_model *m, int k)
{
    double x = k / (NR - 1.0);
    return m->bottom_radius + (m->top_radius - m->bottom_radius) * x * x;
}

double atmosphere_ms_mu(int a) { return -1.0 + (a + 0.5) * CELL; }

double atmosphere_ms_mu_s(int m) { return ATMOSPHERE_MS_MU_S_MIN + m * (1.0 - ATMOSPHERE_MS_MU_S_MIN) / (NS - 1.0); }

size_t atmosphere_ms_index(int k, int a, int m) { return ((size_t)k * NMU + a) * NS + m; }

void atmosphere_ms_lookup(const atmosphere_model *m, const double *field, double r, double mu, double mu_s,
                          double out[3])
{
    double h = fmax(0.0, (r - m->bottom_radius) / (m->top_radius - m->bottom_radius));
    atmosphere_grid_axis x = atmosphere_grid_axis_at((NR - 1) * sqrt(h), NR);
    atmosphere_grid_axis y = atmosphere_grid_axis_at((mu + 1.0) / CELL - 0.5, NMU);
    atmosphere_grid_axis z = atmosphere_grid_axis_at((mu_s - ATMOSPHERE_MS_MU_S_MIN) / (1.0 - ATMOSPHERE_MS_MU_S_MIN) *
                                                         (NS - 1),
                                                     NS);
    int ks[2] = {x.i0, x.i1}, as[2] = {y.i0, y.i1}, ms[2] = {z.i0, z.i1};
    double wk[2] = {1 - x.w, x.w}, wa[2] = {1 - y.w, y.w}, wm[2] = {1 - z.w, z.w};
    for (int c = 0; c < 3; ++c)
        out[c] = 0.0;
    for (int i = 0; i < 8; ++i) {
        double w = wk[i & 1] * wa[(i >> 1) & 1] * wm[i >> 2];
        const double *v = field + 3 * atmosphere_ms_index(ks[i & 1], as[(i >> 1) & 1], ms[i >> 2]);
        for (int c = 0; c < 3; ++c)
            out[c] += w * v[c];
    }
}
