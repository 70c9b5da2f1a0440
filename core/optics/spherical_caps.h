/* Spherical caps: the set of unit directions within angle a of an axis.
 *
 *   solid angle of a cap           2 pi (1 - cos a)
 *   solid angle of the intersection of two caps (angular radii a1, a2 in
 *   [0, pi], axes gamma apart), exactly:
 *
 *     Omega = 2 [ pi - acos((cos g - cos a1 cos a2) / (sin a1 sin a2))
 *                    - cos a1 acos((cos a2 - cos g cos a1) / (sin g sin a1))
 *                    - cos a2 acos((cos a1 - cos g cos a2) / (sin g sin a2)) ]
 *
 *   when the two boundary circles cross (|a1 - a2| < g < a1 + a2 and
 *   g < 2 pi - a1 - a2): Tovchigrechko and Vakser 2001, "How common is the
 *   funnel-like energy landscape in protein-protein interactions?", Protein
 *   Science 10, appendix; derived independently by Mazonka 2012, "Solid Angle
 *   of Conical Surfaces, Polyhedral Cones, and Intersecting Spherical Caps"
 *   (arXiv:1205.1396), eq. 30. (The GTSO talk cites both as "mathematically
 *   equivalent"; tests/core checks this form against Mazonka's own
 *   derivation, two cones cut by a plane, to 1e-12 on a dense grid.) The three terms are the Gauss-Bonnet sum over the lune's
 *   two vertices and two arcs. The other cases are: one cap inside the other
 *   (the smaller cap's solid angle), disjoint caps (0), and caps whose union
 *   is the whole sphere (Omega1 + Omega2 - 4 pi).
 *
 * Tested against brute-force Monte Carlo on the sphere (tests/core). */
#ifndef GTLAB_CORE_OPTICS_SPHERICAL_CAPS_H
#define GTLAB_CORE_OPTICS_SPHERICAL_CAPS_H

/* 2 pi (1 - cos a) for a cap of angular radius a, given cos a. */
double spherical_cap_solid_angle(double cos_a);

/* The exact solid angle of the intersection of caps of angular radii a1, a2
 * (radians, [0, pi]) whose axes are gamma apart (radians, [0, pi]). */
double spherical_cap_intersection(double a1, double a2, double gamma);

/* The same by Mazonka 2012's derivation (two cones cut by the plane through
 * the boundary circles' crossings), for crossing configurations only
 * (|a1 - a2| < gamma < min(a1 + a2, 2 pi - a1 - a2)). */
double spherical_cap_intersection_mazonka(double a1, double a2, double gamma);

/* The largest |difference| of the two derivations over the crossing
 * configurations of an n^3 grid of (a1, a2, gamma) in (0, pi)^3, offset so
 * no point lies within 1e-4 of a case boundary (where acos near +-1 turns
 * rounding of 1e-16 into 1e-8), caps up to pi - 0.05 (closer to pi the
 * Gauss-Bonnet form divides by sin a -> 0: 2.3e-12 at a = 3.12, of a solid
 * angle near 4 pi). *compared receives the number of configurations. */
double spherical_caps_compare_derivations(int n, long *compared);

#endif
