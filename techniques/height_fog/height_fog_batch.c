/* The published HeightFog() over a row of pixels (height_fog/height_fog.h):
 * height_fog_published's steps (height_fog/height_fog_published.h) in loops
 * GCC vectorises at -O3. gtlab compiles with -fno-math-errno (errno is never
 * read), so expf and sqrtf are pure, and here expf is declared with GCC's
 * simd attribute, which tells the vectoriser that glibc's libmvec has its
 * vector variants (_ZGVbN4v_expf on the x86-64 baseline; libm.so links
 * libmvec as needed). glibc's math.h declares them so only under
 * -ffast-math, which gtlab does not use: the arithmetic stays IEEE and only
 * expf's last bits differ from the scalar function. */
#include <stddef.h>
#include <string.h>

#include "height_fog/height_fog_published.h"

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
__attribute__((__simd__("notinbranch"))) float expf(float);
#endif

/* Pixels per group. Every group is computed whole, from local copies (a
 * short last group padded with a harmless view), so each pixel goes through
 * the same vector code wherever it falls: no scalar prologue or epilogue,
 * and the same bits for any split of a row into calls. */
#define HEIGHT_FOG_GROUP 64

typedef struct {
    _Alignas(16) float distance[HEIGHT_FOG_GROUP], world_y[HEIGHT_FOG_GROUP], sov[HEIGHT_FOG_GROUP];
    _Alignas(16) float inscatter[3][HEIGHT_FOG_GROUP], transmittance[3][HEIGHT_FOG_GROUP];
} height_fog_group;

/* The published model over one whole group; the clamp's select in its own
 * loop (GCC 12 does not if-convert a loop that also calls a vector function). */
static void height_fog_group_run(const height_fog_uniforms *restrict u, float camera_y, height_fog_group *restrict g)
{
    float clamped[HEIGHT_FOG_GROUP];
    for (int i = 0; i < HEIGHT_FOG_GROUP; ++i)
        clamped[i] = height_fog_clamped_t(u, camera_y, g->world_y[i]);
    for (int i = 0; i < HEIGHT_FOG_GROUP; ++i) {
        float t = height_fog_published_density(u, clamped[i], g->world_y[i]), mu = g->sov[i];
        float pr = height_fog_rayleigh(mu), pm = height_fog_henyey_greenstein(u, mu), x = -g->distance[i] * t;
        for (int c = 0; c < 3; ++c) {
            float transmittance = expf(x * u->beta_t[c]);
            g->transmittance[c][i] = transmittance;
            g->inscatter[c][i] = height_fog_source(u, c, height_fog_single(u, c, pr, pm)) * (1.0f - transmittance);
        }
    }
}

void height_fog_published_batch(const height_fog_uniforms *u, float camera_y, size_t n, const float *distance,
                                const float *world_y, const float *sov, float *const inscatter[3],
                                float *const transmittance[3])
{
    height_fog_group g;
    for (size_t s = 0; s < n; s += HEIGHT_FOG_GROUP) {
        size_t m = n - s < HEIGHT_FOG_GROUP ? n - s : HEIGHT_FOG_GROUP;
        for (size_t i = 0; i < HEIGHT_FOG_GROUP; ++i) { /* padding: a view one scale height down, no distance */
            g.distance[i] = i < m ? distance[s + i] : 0.0f;
            g.world_y[i] = i < m ? world_y[s + i] : camera_y - u->scale_height;
            g.sov[i] = i < m ? sov[s + i] : 0.0f;
        }
        height_fog_group_run(u, camera_y, &g);
        for (int c = 0; c < 3; ++c) {
            memcpy(inscatter[c] + s, g.inscatter[c], m * sizeof(float));
            memcpy(transmittance[c] + s, g.transmittance[c], m * sizeof(float));
        }
    }
}
