/* Multi-bounce ambient occlusion (DESIGN.md "Definitions"; the GTAO talk,
 * "Multiple Bounces"): the radiance L leaving a Lambertian surface of albedo
 * rho under a uniform white dome of radiance 1, every surface of albedo rho,
 * divided by rho. With L(x) = (rho / pi) \int L_in(x, w) (n.w) dw and
 * cosine-weighted directions (pdf (n.w) / pi) a bounce multiplies the path's
 * throughput by exactly rho, so
 *   V'_d = L / rho = sum_k rho^k P(a path from the pixel's surface escapes
 *                                   after exactly k inter-reflections)
 * and one geometric path serves every albedo: it adds rho^k to each. The
 * k = 0 term alone is V_d (ao.V). No radiance here exceeds the dome's (a
 * bounce reflects a fraction rho <= 1 of a mean of radiances <= 1), so
 * 0 <= V_d <= V'_d <= 1, and so does every sample (a path escapes at most
 * once, carrying at most 1): the film's scale exponent is 0.
 *
 * --bounces N counts inter-reflections after the first hit (N = 0: V'_d =
 * V_d). MULTIBOUNCE_UNLIMITED continues paths by Russian roulette: at each
 * new vertex the path survives with probability q = the largest albedo
 * estimated there (a constant for grey albedos, so it does not depend on the
 * albedo and one path still serves all), and its throughput is multiplied by
 * rho / q <= 1. Unbiased, except that a path is ended after
 * MULTIBOUNCE_PATH_LIMIT inter-reflections: the bias is below the chance of
 * surviving that many rounds, q^1024 (< 1e-46 for q <= 0.9); it matters only
 * where q = 1 (surfaces of albedo 1), where it is what ends the paths of a
 * closed room (whose answer, 0, it does not change).
 *
 * Albedos: several uniform grey ones in one pass, or the scene's glTF base
 * colour (textures included; metallic ignored: the surfaces are Lambertian;
 * values clamped to [0, 1]) at every vertex, per colour channel. For the
 * coloured estimate rho is the albedo of the shading point (the pixel's own
 * surface, its albedo.* G-buffer channels): L / rho_c = E[prod of rho_c over
 * the later vertices], well defined even where rho_c = 0.
 *
 * Channels (film quantities, in this order; quantity 0 drives the stop rule):
 *   one grey albedo       multibounce.V
 *   several grey albedos  multibounce_<rho>.V for each, in the order given,
 *                         rho written as the shortest decimal that reads
 *                         back as the same float ("multibounce_0.3.V")
 *   scene albedo          multibounce.R, multibounce.G, multibounce.B
 *   always                ao.V: V_d, the escape of the first cosine ray
 *                         (the AO integrator's estimator)
 * The header records ATTR_ALBEDOS ("0.1 0.3 0.5" or "scene") and
 * ATTR_BOUNCES ("4" or "inf").
 *
 * Sampling: the direction leaving vertex d (d = 0: the pixel's surface) uses
 * dimension pair d (pair 0 is the AO integrator's); the roulette decision at
 * vertex d uses the first coordinate of pair MULTIBOUNCE_ROULETTE_PAIRS + d.
 * Rays leave p offset along the geometric normal; the hemisphere is built on
 * the shading normal (or the geometric one, normal_mode), and a direction
 * below the geometric surface ends the path: the surface blocks it. */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_INTEGRATOR_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_INTEGRATOR_H

#include <stddef.h>

#include "core/reference_schema.h"
#include "raytracer/diffuse_path_albedos.h"
#include "raytracer/render_loop.h"

/* The albedos and bounces (multibounce_settings) and their limits are the
 * diffuse path tracers' (raytracer/diffuse_path_albedos.h). */
enum { MULTIBOUNCE_MAX_QUANTITIES = MULTIBOUNCE_MAX_ALBEDOS + 1 };

/* "0.1,0.3,0.5" or "scene" (the --albedo option). Errors name "--albedo". */
int multibounce_parse_albedos(const char *text, multibounce_settings *s, gt_error *e);
/* "N" (0 .. MULTIBOUNCE_PATH_LIMIT) or "inf" (the --bounces option). */
int multibounce_parse_bounces(const char *text, multibounce_settings *s, gt_error *e);

/* The header texts: albedos "0.1 0.3 0.5" or "scene"; bounces "4" or "inf". */
void multibounce_albedos_text(const multibounce_settings *s, char *text, size_t size);
void multibounce_bounces_text(const multibounce_settings *s, char *text, size_t size);

/* The world a path's rays meet. For the rays[r].ray (origin, direction;
 * r < n), escaped[r] = 1 when ray r leaves the world, else 0 and, unless
 * `last` (the path's last ray: only whether it escapes matters), hits[r]
 * the surface it meets (at least `parts` of it, embree_scene.h), normals
 * facing the side the ray came from. The 3-D scene (Embree streams) when a
 * plan's world has no trace; the depth buffer as a height field in
 * heightfield_multibounce_integrator.h. */
typedef struct {
    void (*trace)(const void *data, struct RTCRayHit *rays, int n, int last, unsigned parts, unsigned char *escaped,
                  surface_hit *hits);
    const void *data;
} multibounce_world;

/* Everything the integrator reads: the validated settings, the normal
 * mode, the film quantities named as above, and the world (zero: the 3-D
 * scene). */
typedef struct {
    multibounce_settings settings;
    normal_mode normals;
    int quantity_count;
    mc_quantity quantities[MULTIBOUNCE_MAX_QUANTITIES];
    multibounce_world world;
} multibounce_plan;

/* Validates the settings (errors name "multibounce") and names the channels. */
int multibounce_plan_init(multibounce_plan *plan, const multibounce_settings *s, normal_mode normals, gt_error *e);

/* Warns (gt_warn) when the scene has base colours outside [0, 1], which
 * glTF forbids and the scene-albedo estimate clamps. */
void multibounce_warn_albedo_range(const scene *s);

/* The integrator; `plan` must outlive it. */
integrator multibounce_integrator(const embree_scene *es, const multibounce_plan *plan);

#endif
