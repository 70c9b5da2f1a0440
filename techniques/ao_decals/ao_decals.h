/* INSIDE's analytic AO decals (Gjoel, GDC 2016, seed 002, "AO Decals") and
 * the exact forms they approximate (issue 17, item 1). Every function
 * returns an OCCLUSION a in [0, 1]: the share of the cosine-weighted
 * hemisphere the occluder covers, so the visibility V_d of gtlab's AO
 * reference (techniques/ao/ao_integrator.h) is 1 - a for one occluder. Decals
 * are blended multiplicatively (Src: Zero, Dst: SrcColor): N decals give
 * prod (1 - a_i), not the union's 1 - a_union (reported, not hidden).
 *
 * Point decal, as published (the decal's unit sphere after its full
 * transform; `pos` the shaded point in that space, `norm` its normal there):
 *     nDotL = dot(normalize(pos), norm) * 0.5 + 0.5;
 *     falloff = 1.0 - length(pos);
 *     ao = falloff * falloff * nDotL;
 * "a regular half lambert point light, made multiplicative". Two readings
 * are needed to use it: (1) ao multiplying the colour would be 0 (black) at
 * the decal's rim and nDotL at its centre, so it is the occlusion and the
 * multiplier is 1 - intensity * ao; (2) a light at the decal's centre has
 * L = normalize(centre - p) = -normalize(pos), so with pos = p - centre the
 * published sign darkens the side facing away from the occluder; the
 * function takes the vector the talk calls pos and the caller chooses
 * (ao_point_decal_published is the text; the study scores both signs).
 * The general form has the free constants a refit needs: falloff exponent
 * k (2 published) and wrap w (1 published: (dot + w) / (1 + w)).
 *
 * Sphere (Quilez 2006, "sphere ambient occlusion"): a = n.d / |d| * (r/|d|)^2
 * with d the vector to the centre: exact while the whole sphere is above
 * the tangent plane (cos theta > sin sigma), as the talk assumes; the exact
 * horizon-clipped form is Lagarde and de Rousiers 2014's illuminance of a
 * sphere (realtime/sphere_illuminance.h) over pi.
 *
 * Box: the talk's box decal is empirical ("not physically accurate in any
 * way") and its code is not in the text; gtlab's exact form is Lambert's
 * polygon form factor (Lambert 1760; Baum, Rushmeier and Winget 1989, eq. 1)
 *     a = 1/(2 pi) sum over edges of angle(u_i, u_i+1) n.normalize(u_i x u_i+1)
 * summed over the box faces that face the point, each face first clipped to
 * the tangent half-space n.(x - p) >= 0 (a convex box's front faces tile its
 * silhouette without overlap). */
#ifndef GTLAB_AO_DECALS_AO_DECALS_H
#define GTLAB_AO_DECALS_AO_DECALS_H

#include "core/vec3.h"

/* The talk's three lines: falloff^2 * (dot(normalize(pos), norm) * 0.5 + 0.5),
 * with the falloff clamped at 0 outside the unit sphere (the decal mesh
 * bounds the pixels it shades). */
float ao_point_decal_published(vec3 pos, vec3 norm);

/* A decal volume: the unit sphere under the talk's "full transform" x -> centre + half * x (per axis;
 * axis-aligned here, a rotation would only rotate both vectors below). */
typedef struct {
    vec3 centre, half;
} ao_decal_volume;

/* The shaded point p with unit normal n in the volume's unit space: pos = (p - centre) / half (the
 * talk's `pos`; the light's is -pos) and norm = normalize(half * n), the normal mapped by the inverse
 * transpose of the point map x -> x / half, so that norm stays perpendicular to the mapped surface. */
void ao_decal_unit_space(vec3 p, vec3 n, const ao_decal_volume *v, vec3 *pos, vec3 *norm);

/* max(0, 1 - |pos|)^exponent * max(0, (dot(normalize(pos), norm) + wrap) / (1 + wrap)). */
float ao_point_decal(vec3 pos, vec3 norm, float exponent, float wrap);

/* Quilez's sphere occlusion at p with normal n (unit), clamped to [0, 1]. */
float ao_sphere_quilez(vec3 p, vec3 n, vec3 centre, float radius);

/* The exact cosine-weighted occlusion of a sphere not containing p, clipped at the horizon. */
float ao_sphere_exact(vec3 p, vec3 n, vec3 centre, float radius);

/* The exact cosine-weighted occlusion of the axis-aligned box [lo, hi] seen from p outside it. */
double ao_box_exact(vec3 p, vec3 n, vec3 lo, vec3 hi);

/* The form factor of one planar polygon (count <= 8 vertices, world space) from p with normal n,
 * clipped at the horizon: its projected solid angle over pi. */
double ao_polygon_form_factor(vec3 p, vec3 n, const vec3 *vertices, int count);

#endif
