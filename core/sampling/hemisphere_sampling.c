#include "core/sampling/hemisphere_sampling.h"

/* sin s and cos s for s in [-pi/4, pi/4]: the single-precision minimax
 * polynomials of Cephes' sinf/cosf (S. L. Moshier, 1992), within about 1e-7.
 * Plain IEEE arithmetic (no library call), so a batch loop vectorises and
 * every CPU gives the same bits. */
static inline void sincos_wedge(float s, float *sine, float *cosine)
{
    float s2 = s * s;
    *sine = s + s * s2 * (-1.6666654611e-1f + s2 * (8.3321608736e-3f + s2 * -1.9515295891e-4f));
    *cosine = 1.0f - 0.5f * s2 +
              s2 * s2 * (4.166664568298827e-2f + s2 * (-1.388731625493765e-3f + s2 * 2.443315711809948e-5f));
}

static inline void concentric_disc(float u0, float u1, float *x, float *y)
{
    /* Shirley & Chiu 1997: the square [-1,1]^2 mapped wedge by wedge, the
     * angle being phi = (pi/4) b/a in the left and right wedges and
     * pi/2 - (pi/4) a/b in the top and bottom ones, where cos and sin swap.
     * Written with selects: with random points a branch on the wedge would
     * mispredict half the time. */
    float a = 2.0f * u0 - 1.0f, b = 2.0f * u1 - 1.0f;
    int left_right = fabsf(a) > fabsf(b);
    float r = left_right ? a : b;
    /* r = 0 only at the centre, where the numerator is 0 as well. */
    float ratio = (left_right ? b : a) / (r != 0.0f ? r : 1.0f);
    float sine, cosine;
    sincos_wedge((float)(M_PI / 4) * ratio, &sine, &cosine);
    *x = r * (left_right ? cosine : sine);
    *y = r * (left_right ? sine : cosine);
}

/* The smallest z kept: rounding near the disc's rim could otherwise give
 * z = 0, a direction on the horizon (a change on a set of measure zero). */
static const float min_z = 0x1p-12f;

static inline vec3 cosine_from_disc(float x, float y)
{
    float z2 = 1.0f - x * x - y * y;
    return v3(x, y, sqrtf(z2 > min_z * min_z ? z2 : min_z * min_z));
}

/* Equal-area map of the unit disc onto the hemisphere: z = 1 - r^2 is
 * uniform when the disc point is, and the horizontal radius
 * sqrt(1 - z^2) = r sqrt(2 - r^2). */
static inline vec3 uniform_from_disc(float x, float y)
{
    float r2 = x * x + y * y;
    float z = 1.0f - r2;
    float scale = sqrtf(2.0f - r2);
    return v3(x * scale, y * scale, z > min_z ? z : min_z);
}

void sample_concentric_disc(const float u[2], float *x, float *y) { concentric_disc(u[0], u[1], x, y); }

vec3 sample_cosine_hemisphere(const float u[2])
{
    float x, y;
    concentric_disc(u[0], u[1], &x, &y);
    return cosine_from_disc(x, y);
}

vec3 sample_uniform_hemisphere(const float u[2])
{
    float x, y;
    concentric_disc(u[0], u[1], &x, &y);
    return uniform_from_disc(x, y);
}

#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target_clones("avx2", "default")))
#endif
void sample_hemisphere_batch(const float *restrict u0, const float *restrict u1, int count, vec3 *restrict cosine,
                             vec3 *restrict uniform)
{
    for (int k = 0; k < count; ++k) {
        float x, y;
        concentric_disc(u0[k], u1[k], &x, &y);
        cosine[k] = cosine_from_disc(x, y);
        uniform[k] = uniform_from_disc(x, y);
    }
}

#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target_clones("avx2", "default")))
#endif
void sample_cosine_hemisphere_batch(const float *restrict u0, const float *restrict u1, int count,
                                    vec3 *restrict cosine)
{
    for (int k = 0; k < count; ++k) {
        float x, y;
        concentric_disc(u0[k], u1[k], &x, &y);
        cosine[k] = cosine_from_disc(x, y);
    }
}
