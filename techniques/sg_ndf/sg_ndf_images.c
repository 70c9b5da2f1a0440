/* Specular images of an NDF and of its SG fit (see sg_ndf_images.h). */
#include "sg_ndf/sg_ndf_images.h"

#include <math.h>
#include <string.h>

#include "core/optics/sky_environment.h"
#include "core/sampling/sobol.h"

/* The sphere's normal at pixel (x, y); 0 off the sphere. */
static int pixel_normal(int size, int x, int y, double n[3])
{
    double px = 2.0 * (x + 0.5) / size - 1.0, py = 1.0 - 2.0 * (y + 0.5) / size, r2 = px * px + py * py;
    if (r2 >= 1.0)
        return 0;
    n[0] = px;
    n[1] = py;
    n[2] = sqrt(1.0 - r2);
    return 1;
}

void sg_image_mask(int size, float *mask)
{
    double n[3];
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            mask[(size_t)y * size + x] = (float)pixel_normal(size, x, y, n);
}

/* t = normalize(Y x n) = normalize(n.z, 0, -n.x); b = n x t. */
static void tangent_frame(const double n[3], double t[3], double b[3])
{
    double len = hypot(n[2], n[0]);
    t[0] = len > 1e-12 ? n[2] / len : 1.0;
    t[1] = 0.0;
    t[2] = len > 1e-12 ? -n[0] / len : 0.0;
    b[0] = n[1] * t[2] - n[2] * t[1];
    b[1] = n[2] * t[0] - n[0] * t[2];
    b[2] = n[0] * t[1] - n[1] * t[0];
}

typedef struct {
    const anisotropic_ndf *ndf;
    const spherical_gaussian *lobes;
    int count;
    double cdf[SG_IMAGE_MAX_LOBES + 1]; /* lobe choice, cumulative I_j / sum I_j */
    double total;                       /* sum I_j */
} sampler;

/* L_sky(r) [r.n > 0] for the local microfacet normal m (frame t, b, n). */
static double reflected_sky(const double m_local[3], const double t[3], const double b[3], const double n[3])
{
    double m[3], r[3];
    for (int i = 0; i < 3; ++i)
        m[i] = t[i] * m_local[0] + b[i] * m_local[1] + n[i] * m_local[2];
    double vm = m[2]; /* v = +z */
    for (int i = 0; i < 3; ++i)
        r[i] = 2.0 * vm * m[i] - (i == 2);
    if (r[0] * n[0] + r[1] * n[1] + r[2] * n[2] <= 0.0)
        return 0.0;
    return sky_radiance(v3((float)r[0], (float)r[1], (float)r[2]));
}

/* One sample's weight from the pixel's point i. */
static double sample_weight(const sampler *s, uint32_t seed, uint32_t i, const double t[3], const double b[3],
                            const double n[3])
{
    float uf[2], pick[2];
    sobol_owen_2d(seed, i, 0, uf);
    double u[2] = {uf[0], uf[1]}, m[3];
    if (s->ndf) {
        anisotropic_ndf_sample(s->ndf, u, m);
        return reflected_sky(m, t, b, n);
    }
    sobol_owen_2d(seed, i, 1, pick);
    int j = 0;
    while (j < s->count - 1 && pick[0] >= s->cdf[j + 1])
        ++j;
    sg_sample(&s->lobes[j], u, m);
    return m[2] > 0.0 ? s->total * m[2] * reflected_sky(m, t, b, n) : 0.0;
}

static void render_pixel(const sampler *s, const sg_image_options *o, int x, int y, const sg_image_planes *out)
{
    size_t p = (size_t)y * o->size + x;
    double n[3], t[3], b[3], sum[2] = {0.0, 0.0}, sum2 = 0.0;
    if (pixel_normal(o->size, x, y, n)) {
        tangent_frame(n, t, b);
        uint32_t seed = pixel_seed(o->seed, (uint32_t)x, (uint32_t)y);
        for (int i = 0; i < o->samples; ++i) {
            double w = sample_weight(s, seed, (uint32_t)i, t, b, n);
            sum[i & 1] += w;
            sum2 += w * w;
        }
    }
    double count = o->samples, mean = (sum[0] + sum[1]) / count;
    double var = fmax(0.0, sum2 / count - mean * mean) / (count - 1.0);
    if (out->mean)
        out->mean[p] = (float)mean;
    if (out->stderr_)
        out->stderr_[p] = (float)sqrt(var);
    if (out->half_even)
        out->half_even[p] = (float)(2.0 * sum[0] / count);
    if (out->half_odd)
        out->half_odd[p] = (float)(2.0 * sum[1] / count);
}

static int sampler_init(sampler *s, const anisotropic_ndf *ndf, const spherical_gaussian *lobes, int count,
                        gt_error *e)
{
    memset(s, 0, sizeof *s);
    s->ndf = ndf;
    s->lobes = lobes;
    s->count = count;
    if (ndf)
        return 0;
    if (count < 1 || count > SG_IMAGE_MAX_LOBES)
        return gt_error_set(e, "sg-ndf images", "lobe count %d outside 1..%d", count, SG_IMAGE_MAX_LOBES);
    for (int j = 0; j < count; ++j) {
        s->cdf[j + 1] = s->cdf[j] + sg_sphere_integral(lobes[j].sharpness, lobes[j].amplitude);
        if (!(lobes[j].amplitude >= 0.0) || !(lobes[j].sharpness > 0.0))
            return gt_error_set(e, "sg-ndf images", "lobe %d has sharpness %g, amplitude %g", j + 1,
                                lobes[j].sharpness, lobes[j].amplitude);
    }
    s->total = s->cdf[count];
    for (int j = 1; j <= count; ++j)
        s->cdf[j] /= s->total;
    return 0;
}

int sg_image_render(const anisotropic_ndf *ndf, const spherical_gaussian *lobes, int count,
                    const sg_image_options *o, const sg_image_planes *out, gt_error *e)
{
    if (o->size < 16 || o->samples < 2 || (o->samples & 1) || o->threads < 1)
        return gt_error_set(e, "sg-ndf images", "size %d, samples %d or threads %d invalid", o->size, o->samples,
                            o->threads);
    sampler s;
    if (sampler_init(&s, ndf, lobes, count, e) != 0)
        return -1;
#pragma omp parallel for schedule(dynamic, 1) num_threads(o->threads)
    for (int y = 0; y < o->size; ++y)
        for (int x = 0; x < o->size; ++x)
            render_pixel(&s, o, x, y, out);
    return 0;
}
