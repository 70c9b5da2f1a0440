/* The height-field control variate's per-pixel horizons; see
 * ao_control_variate.h. */
#include "ao/ao_control_variate.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_integrator.h"
#include "ao/heightfield_ao_integrator.h"

static const char *const mode_names[] = {"none", "heightfield"};

const char *ao_control_variate_name(ao_control_variate mode) { return mode_names[mode]; }

int ao_control_variate_parse(const char *name, ao_control_variate *mode)
{
    for (int m = 0; m < 2; ++m)
        if (strcmp(name, mode_names[m]) == 0) {
            *mode = (ao_control_variate)m;
            return 0;
        }
    return -1;
}

/* The horizons of one covered pixel: its surface point, seen from the eye,
 * and its shading normal (the hemisphere the AO samples cover). */
static void pixel_horizons(const heightfield_settings *hs, const surface_hit *hit, slice_horizons *h)
{
    vec3 v = v3_normalize(v3_sub(hs->gb->view.origin, hit->p));
    float theta[SLICE_HORIZON_SIDES];
    h->v = v;
    frame f = slice_horizons_frame(h);
    for (int k = 0; k < SLICE_HORIZON_SIDES; ++k)
        theta[k] = heightfield_horizon(hs, hit->p, hit->ns, v, slice_horizons_side(&f, k));
    slice_horizons_init(h, v, hit->ns, theta);
}

/* Cov(V, g) / Var(g) over the pilot, clamped to [0, 1]; 1 when g is constant. */
static float pilot_beta(const float *v, const float *g, int n)
{
    double mv = 0.0, mg = 0.0, cov = 0.0, var = 0.0;
    for (int k = 0; k < n; ++k)
        mv += v[k], mg += g[k];
    mv /= n, mg /= n;
    for (int k = 0; k < n; ++k)
        cov += (v[k] - mv) * (g[k] - mg), var += (g[k] - mg) * (g[k] - mg);
    return var > 0.0 ? (float)fmin(fmax(cov / var, 0.0), 1.0) : 1.0f;
}

/* Both coefficients of pixel i from its pilot (see ao_control_variate.h). */
static void pixel_betas(const embree_scene *es, const gbuffer *gb, float max_distance, long i, slice_horizons *h)
{
    pixel_context px = pixel_context_prepare(
        &gb->hits[i], pixel_seed(AO_CONTROL_VARIATE_PILOT_SEED, (uint32_t)(i % gb->width), (uint32_t)(i / gb->width)));
    _Alignas(16) struct RTCRay rays[2 * AO_CONTROL_VARIATE_PILOT];
    ao_trace_batch(es, &px, max_distance, 0.0f, 1, 0, AO_CONTROL_VARIATE_PILOT, rays);
    frame f = slice_horizons_frame(h);
    float v[2][AO_CONTROL_VARIATE_PILOT], g[2][AO_CONTROL_VARIATE_PILOT];
    for (int r = 0; r < 2 * AO_CONTROL_VARIATE_PILOT; ++r) {
        v[r & 1][r >> 1] = rays[r].tfar >= 0.0f ? 1.0f : 0.0f;
        g[r & 1][r >> 1] = slice_horizons_visible(h, &f, v3(rays[r].dir_x, rays[r].dir_y, rays[r].dir_z));
    }
    for (int q = 0; q < 2; ++q)
        h->beta[q] = pilot_beta(v[q], g[q], AO_CONTROL_VARIATE_PILOT);
}

int ao_control_variate_build(ao_control_variate_field *field, const embree_scene *es, const gbuffer *gb,
                             float max_distance, int threads)
{
    field->pixel_count = (long)gb->width * gb->height;
    field->pixels = malloc(sizeof *field->pixels * (size_t)field->pixel_count);
    heightfield_settings hs;
    if (!field->pixels || heightfield_settings_init(&hs, gb, max_distance) != 0) {
        free(field->pixels);
        field->pixels = NULL;
        return -1;
    }
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads)
    for (long i = 0; i < field->pixel_count; ++i) {
        if (gb->mask[i]) {
            pixel_horizons(&hs, &gb->hits[i], &field->pixels[i]);
            pixel_betas(es, gb, max_distance, i, &field->pixels[i]);
        } else
            slice_horizons_off(&field->pixels[i], v3(0.0f, 0.0f, 1.0f));
    }
    heightfield_settings_free(&hs);
    return 0;
}

void ao_control_variate_free(ao_control_variate_field *field)
{
    free(field->pixels);
    field->pixels = NULL;
}
