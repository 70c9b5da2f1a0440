/* The cone-visibility V_s at the actual view against what is known of it:
 * a cone of half-angle 90 degrees about the normal holds every direction
 * above the surface (exactly 1), an empty cone none (exactly 0), and at
 * normal incidence, where the 3-D table's assumption n = v = R holds, its
 * mean over seeds is the table's function so_cone_lobe (adaptive quadrature
 * about R, an independent method) within 4 standard errors of that mean. */
#include <math.h>

#include "specular_occlusion/cone_visibility_view.h"
#include "specular_occlusion/specular_occlusion_lut.h"
#include "tests/check.h"

static vec3 unit(double theta, double phi)
{
    return v3((float)(sin(theta) * cos(phi)), (float)(sin(theta) * sin(phi)), (float)cos(theta));
}

int main(void)
{
    const double pi = 3.14159265358979323846;
    for (int k = 0; k < 5; ++k) {
        vec3 v = unit(0.3 * k, 0.7 * k);
        double alpha = 0.05 + 0.2 * k;
        CHECK(so_cone_visibility_view(v, v3(0, 0, 1), 0.0, alpha, 8, 1u) == 1.0);
        CHECK(so_cone_visibility_view(v, v3(0, 0, 1), 1.5, alpha, 8, 1u) == 0.0);
    }
    double worst = 0.0, worst_single = 0.0;
    for (int r = 1; r <= 4; ++r)
        for (int a = 1; a <= 4; ++a)
            for (int b = 0; b <= 4; ++b) {
                double roughness = 0.2 * r, av = a * pi / 10.0, beta = b * pi / 8.0;
                double lut = so_cone_lobe(SO_LOBE_GGX, av, beta, roughness, so_lobe_normaliser(SO_LOBE_GGX, roughness),
                                          NULL);
                enum { SEEDS = 32 };
                double sum = 0.0, sum_sq = 0.0;
                for (uint32_t seed = 0; seed < SEEDS; ++seed) {
                    double x = so_cone_visibility_view(v3(0, 0, 1), unit(beta, 0.4), cos(av), roughness * roughness, 24,
                                                       seed);
                    sum += x, sum_sq += x * x;
                }
                double mean = sum / SEEDS, se = sqrt(fmax(0.0, sum_sq / SEEDS - mean * mean) / (SEEDS - 1));
                worst = fmax(worst, fabs(mean - lut) / fmax(se, 1e-12));
                worst_single = fmax(worst_single, se * sqrt((double)SEEDS));
                CHECK_MSG(fabs(mean - lut) < 4.0 * se + 1e-7, "r %.2f a_v %.3f beta %.3f: %.5f +- %.5f vs %.5f",
                          roughness, av, beta, mean, se, lut);
            }
    printf("normal incidence, 24x24 strata: worst |mean - table| %.2f standard errors; one estimate's sd up to %.2e\n",
           worst, worst_single);
    return check_report("test_cone_visibility_view");
}
