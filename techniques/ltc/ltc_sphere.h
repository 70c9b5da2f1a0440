/* Sphere lights by linearly transformed cosines, in C as a shader would
 * evaluate them (conventions of sphere_light/sphere_light.h: local frame n = +z,
 * the light by its centre direction lc and sin(sigma); the specular returns
 * radiance per unit normal illuminance).
 *
 * Heitz, Dupuy, Hill & Neubelt 2016, "Real-Time Polygonal-Light Shading
 * with Linearly Transformed Cosines": the integral of the LTC D over a
 * polygon P is the form factor of the polygon M^-1 P, clipped to the
 * cosine's hemisphere z >= 0, which Lambert's formula for a polygon gives
 * in closed form (Arvo 1995, "Applications of Irradiance Tensors"):
 *
 *   F(P) = 1/(2 pi) sum_edges theta_ij (p_i x p_j).z / |p_i x p_j|,
 *   theta_ij = angle between p_i and p_j
 *
 * (the edge's angle from atan2(|p_i x p_j|, p_i . p_j), exact and stable in
 * float down to the sun's size, instead of the shipped code's fitted
 * theta / sin(theta): see ltc/ltc_sphere.c). Vertices are held as a common centre plus offsets,
 * so the cross products of a tiny polygon's nearly parallel vertices are
 * taken of the offsets (C x (O_j - O_i) + O_i x O_j): no cancellation.
 *
 * Spheres (Heitz & Hill 2017, "Real-Time Line- and Disk-Light Shading with
 * Linearly Transformed Cosines", SIGGRAPH course): the sphere is replaced by
 * the disk facing the shading point that subtends the same cone, the cap
 * of half-angle sigma around lc. gtlab integrates that disk as a regular
 * N-gon in the disk's plane, its circumradius enlarged so that its area is
 * the disk's (rho = tan(sigma) sqrt(2 pi / (N sin(2 pi / N)))), through
 * Heitz 2016's clipped polygon integral, rather than the course's ellipse
 * and sphere form-factor approximation: the polygon route is exact up to
 * the N-gon's own discretisation error, which is measured against a
 * 1024-gon (README.md, "Decisions"), and it reuses the one
 * polygon integral the tests check against closed forms. */
#ifndef GTLAB_LTC_LTC_SPHERE_H
#define GTLAB_LTC_LTC_SPHERE_H

#include "core/vec3.h"
#include "ltc/ltc_ggx.h"

#define LTC_SPHERE_SIDES 8     /* the N-gon of the shipped evaluation */
#define LTC_MAX_SIDES 1024     /* polygons up to this many vertices (before clipping) */

/* The form factor of the polygon with vertices centre + offsets[k]
 * (k < count, directions from the origin, any lengths), clipped to z >= 0:
 * |F(P)| above (either winding). */
float ltc_polygon_form_factor(vec3 centre, const vec3 *offsets, int count);

/* The integral of the LTC with M^-1 = [[a, 0, b], [0, c, 0], [d, 0, 1]]
 * (m = {a, b, c, d}) over the cap of half-angle sigma around lc, for the
 * view v, as an N-gon (sides <= LTC_MAX_SIDES) of equal area. */
float ltc_sphere_integral(const float m[4], vec3 v, vec3 lc, float sin_sigma, int sides);

/* The LTC sphere light's white specular (F0 = 1: the magnitude E) per unit
 * normal illuminance: E ltc_sphere_integral / (pi sin^2 sigma), the table
 * looked up at (v.z, roughness), LTC_SPHERE_SIDES sides. */
float ltc_sphere_ggx(const ltc_table *t, vec3 v, vec3 lc, float sin_sigma, float roughness);

/* The same with Schlick's Fresnel of f0 through the table's Fresnel term:
 * (f0 E + (1 - f0) B) ltc_sphere_integral / (pi sin^2 sigma). */
float ltc_sphere_ggx_fresnel(const ltc_table *t, vec3 v, vec3 lc, float sin_sigma, float roughness, float f0);

/* ltc_sphere_ggx_fresnel as a sphere_specular_fn (sphere_light/sphere_light.h):
 * user is the ltc_table. */
float ltc_sphere_specular(const void *table, vec3 v, vec3 lc, float sin_sigma, float roughness, float f0);

#endif
