/* Phase functions of the atmosphere and of height fog: the angular
 * distribution of light scattered once by a particle, normalised so that
 * its integral over the sphere of directions is 1 [1/sr]. mu is the cosine
 * of the angle between the light's propagation direction and the scattered
 * direction; with the Decima talk's argument dot(sun_dir, view_dir) (sun_dir
 * pointing to the sun, view_dir from the camera), mu = 1 looks into the sun
 * and scatters forward.
 *
 *   Rayleigh (molecules; Chandrasekhar 1960, Bruneton 2017 eq. for
 *   RayleighPhaseFunction):   p_R(mu) = 3 / (16 pi) (1 + mu^2)
 *   Henyey-Greenstein (aerosols, "Mie"; Henyey & Greenstein 1941):
 *                             p_HG(mu, g) = (1 - g^2) / (4 pi (1 + g^2 - 2 g mu)^(3/2))
 *   Cornette-Shanks (the Mie phase of Bruneton 2017 and of Bruneton & Neyret
 *   2008 eq. 5): p_CS(mu, g) = 3 / (8 pi) (1 - g^2) (1 + mu^2)
 *                              / ((2 + g^2) (1 + g^2 - 2 g mu)^(3/2))
 *
 * All three integrate to 1; HG's mean cosine is g, and HG can be sampled
 * exactly by inverting its CDF (Pharr, Jakob, Humphreys, pbrt-v4 §11.3.1),
 * which the Monte Carlo references use. */
#ifndef GTLAB_CORE_OPTICS_PHASE_FUNCTION_H
#define GTLAB_CORE_OPTICS_PHASE_FUNCTION_H

#include "core/vec3.h"

double rayleigh_phase(double mu);
double henyey_greenstein_phase(double mu, double g);
double cornette_shanks_phase(double mu, double g);

/* The cosine mu of a direction drawn from p_HG(., g) with the uniform
 * number u in [0, 1) (pbrt-v4 SampleHenyeyGreenstein, with mu measured
 * from the propagation direction as above); |g| < 1. */
double henyey_greenstein_sample_mu(double g, double u);

/* A unit direction scattered from the propagation direction w (unit) with
 * p_HG(., g), using two uniform numbers; its pdf is p_HG(dot(w, result), g). */
vec3 henyey_greenstein_sample(vec3 w, double g, double u1, double u2);

#endif
