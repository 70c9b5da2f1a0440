/* core/optics/volumetric_light.h: the spot's falloff is pbrt-v4's smoothstep (1 on
 * the axis and inside the inner cone, 0 outside the outer, 1/2 half way in
 * cosine); the analytic ray-cone interval agrees with the falloff sampled
 * densely along random rays (inside the outer cone exactly where the falloff
 * is positive); the integrand is sigma_s / (4 pi r^2) for an isotropic,
 * non-absorbing medium and carries exp(-sigma_t (s + r)) and HG otherwise;
 * bad lights and media are refused. */
#include <math.h>
#include <stdint.h>

#include "core/optics/phase_function.h"
#include "core/optics/volumetric_light.h"
#include "tests/check.h"

static double uniform(uint64_t *state)
{
    *state = *state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*state >> 11) * (1.0 / 9007199254740992.0);
}

static vec3 random_point(uint64_t *state, double half)
{
    return v3((float)(half * (2.0 * uniform(state) - 1.0)), (float)(half * (2.0 * uniform(state) - 1.0)),
              (float)(half * (2.0 * uniform(state) - 1.0)));
}

static vec3 at(vec3 o, vec3 w, double t)
{
    return v3((float)(o.x + t * w.x), (float)(o.y + t * w.y), (float)(o.z + t * w.z));
}

static void check_falloff(const volumetric_light *spot)
{
    vec3 p = spot->position, a = spot->axis;
    CHECK_NEAR(volumetric_light_falloff(spot, v3_add(p, a)), 1.0, 1e-12);
    /* A point at angle theta from the axis. */
    vec3 side = v3_normalize(v3_cross(a, v3(0.0f, 0.0f, 1.0f)));
    double cos_mid = 0.5 * (spot->cos_outer + spot->cos_inner);
    double angles[3] = {acos(cos_mid), acos(spot->cos_outer) + 0.01, acos(spot->cos_inner) - 0.01};
    double expect[3] = {0.5, 0.0, 1.0};
    for (int k = 0; k < 3; ++k) {
        vec3 x = v3_add(p, v3_add(v3_scale(a, (float)cos(angles[k])), v3_scale(side, (float)sin(angles[k]))));
        CHECK_NEAR(volumetric_light_falloff(spot, x), expect[k], 1e-5);
    }
}

/* The interval against the falloff sampled along the ray. */
static void check_cone_interval(const volumetric_light *spot, uint64_t *state)
{
    int hits = 0;
    for (int ray = 0; ray < 400; ++ray) {
        vec3 o = random_point(state, 4.0), w = v3_normalize(random_point(state, 1.0));
        double t0 = 0.0, t1 = 0.0;
        int hit = volumetric_cone_interval(spot, spot->cos_outer, o, w, 0.0, 10.0, &t0, &t1) == 0;
        hits += hit;
        int mismatches = 0;
        for (int k = 0; k < 2000; ++k) {
            double t = 10.0 * (k + 0.5) / 2000.0;
            int inside = hit && t > t0 + 1e-4 && t < t1 - 1e-4, outside = !hit || t < t0 - 1e-4 || t > t1 + 1e-4;
            double f = volumetric_light_falloff(spot, at(o, w, t));
            mismatches += (inside && !(f > 0.0)) || (outside && f > 0.0);
        }
        CHECK_MSG(mismatches == 0, "ray %d: %d of 2000 points disagree with [%g, %g]", ray, mismatches, t0, t1);
    }
    CHECK_MSG(hits > 60 && hits < 400, "%d rays of 400 cross the cone", hits);
}

static void check_density(void)
{
    const double one[3] = {1.0, 1.0, 1.0};
    volumetric_light point = volumetric_point_light(v3(0.0f, 2.0f, 0.0f), one);
    volumetric_medium clear = {0.3, 0.3, 0.0}, thick = {0.2, 0.5, 0.6};
    vec3 o = v3(-3.0f, 0.0f, 0.0f), w = v3(1.0f, 0.0f, 0.0f);
    for (double s = 0.0; s < 6.0; s += 0.75) {
        double dx = 3.0 - s, r2 = dx * dx + 4.0, r = sqrt(r2);
        clear.sigma_t = 0.3, clear.sigma_s = 0.3;
        CHECK_NEAR(volumetric_inscatter_density(&point, &clear, o, w, s),
                   0.3 / (4.0 * M_PI * r2) * exp(-0.3 * (s + r)), 1e-12);
        double mu = dx / r;
        CHECK_NEAR(volumetric_inscatter_density(&point, &thick, o, w, s),
                   0.2 * henyey_greenstein_phase(mu, 0.6) * exp(-0.5 * (s + r)) / r2, 1e-12);
    }
}

static void check_validation(void)
{
    const double one[3] = {1.0, 1.0, 1.0}, negative[3] = {1.0, -1.0, 1.0};
    volumetric_medium bad_g = {0.1, 0.2, 1.0}, bad_sigma = {0.3, 0.2, 0.0}, good = {0.1, 0.2, 0.3};
    volumetric_light wide = volumetric_spot_light(v3(0.0f, 0.0f, 0.0f), v3(0.0f, -1.0f, 0.0f), 20.0, 30.0, one);
    volumetric_light dark = volumetric_point_light(v3(0.0f, 0.0f, 0.0f), negative);
    gt_error e;
    CHECK(volumetric_medium_validate(&good, "m", &e) == 0);
    CHECK(volumetric_medium_validate(&bad_g, "m", &e) != 0);
    CHECK(volumetric_medium_validate(&bad_sigma, "m", &e) != 0);
    CHECK(volumetric_light_validate(&wide, "l", &e) != 0);
    CHECK(volumetric_light_validate(&dark, "l", &e) != 0);
}

int main(void)
{
    const double one[3] = {1.0, 1.0, 1.0};
    uint64_t state = 29;
    volumetric_light spot = volumetric_spot_light(v3(0.3f, 1.0f, -0.2f), v3(0.5f, -2.0f, 0.4f), 35.0, 20.0, one);
    gt_error e;
    CHECK(volumetric_light_validate(&spot, "spot", &e) == 0);
    check_falloff(&spot);
    check_cone_interval(&spot, &state);
    check_density();
    check_validation();
    return check_report("test_volumetric_light");
}
