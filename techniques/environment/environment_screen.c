/* The ambient combinations per pixel: see the header. */
#include "environment/environment_screen.h"

#include <math.h>

static void load3(const float *const c[3], size_t p, double out[3])
{
    out[0] = c[0][p], out[1] = c[1][p], out[2] = c[2][p];
}

static void store3(float *const out[3], size_t p, const double v[3])
{
    out[0][p] = (float)v[0], out[1][p] = (float)v[1], out[2][p] = (float)v[2];
}

void environment_screen_diffuse(const environment_lighting *l, environment_irradiance_source s, environment_diffuse_kind k,
                               const so_screen_buffers *b, const float *const albedo[3], float *const out[3])
{
    size_t count = (size_t)b->width * b->height;
#pragma omp parallel for schedule(static)
    for (size_t p = 0; p < count; ++p) {
        double n[3], bent[3], unit_bent[3], rho[3], o[3] = {0.0, 0.0, 0.0};
        if (b->mask[p] >= 0.5f) {
            load3(b->normal, p, n), load3(b->bent, p, bent), load3(albedo, p, rho);
            environment_unit_bent(bent, n, unit_bent);
            environment_diffuse(l, s, k, n, unit_bent, b->ao_cosine[p], rho, o);
        }
        store3(out, p, o);
    }
}

/* R = 2 (n.v) n - v at pixel p. */
static void reflection(const so_screen_buffers *b, vec3 eye, size_t p, double R[3])
{
    double n[3], pos[3];
    load3(b->normal, p, n), load3(b->position, p, pos);
    double v[3] = {eye.x - pos[0], eye.y - pos[1], eye.z - pos[2]};
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), nv = 0.0;
    for (int c = 0; c < 3; ++c)
        v[c] /= len, nv += n[c] * v[c];
    for (int c = 0; c < 3; ++c)
        R[c] = 2.0 * nv * n[c] - v[c];
}

void environment_screen_specular(const environment_lighting *l, const so_screen_buffers *b, const so_pixel_inputs *in,
                                vec3 eye, double f0, const so_variant *v, float *const out[3])
{
    size_t count = (size_t)b->width * b->height;
    double f[3] = {f0, f0, f0};
#pragma omp parallel for schedule(static)
    for (size_t p = 0; p < count; ++p) {
        double R[3], o[3] = {0.0, 0.0, 0.0};
        if (in->mask[p] >= 0.5f) {
            reflection(b, eye, p, R);
            double vs = v ? so_approx_pixel(in, v, p) : 1.0;
            environment_specular(l, R, in->n_dot_v[p], in->roughness[p], f, vs, o);
        }
        store3(out, p, o);
    }
}
