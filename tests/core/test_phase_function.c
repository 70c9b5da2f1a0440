/* Phase functions against their defining properties: each integrates to 1
 * over the sphere (2 pi times a Simpson rule in mu), HG's mean cosine is g,
 * Rayleigh and Cornette-Shanks are even in mu at g = 0, and the HG sampler's
 * mean cosine and second moment match the density's within 5 standard errors
 * of the run itself; sampled directions lie at the drawn angle from w. */
#include <math.h>

#include "core/optics/phase_function.h"
#include "tests/check.h"

/* 2 pi \int_{-1}^{1} f(mu) mu^k dmu by composite Simpson, n even. */
static double sphere_moment(double (*f)(double, double), double g, int k)
{
    const int n = 20000;
    double h = 2.0 / n, s = 0.0;
    for (int i = 0; i <= n; ++i) {
        double mu = -1.0 + i * h, w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        s += w * f(mu, g) * pow(mu, k);
    }
    return 2.0 * M_PI * s * h / 3.0;
}

static double rayleigh2(double mu, double g) { (void)g; return rayleigh_phase(mu); }

static void check_sampler(double g)
{
    unsigned long long state = 0x9E3779B97F4A7C15ull;
    const int n = 200000;
    double s1 = 0.0, s2 = 0.0;
    for (int i = 0; i < n; ++i) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        double u1 = (double)(state >> 11) * 0x1.0p-53;
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        double u2 = (double)(state >> 11) * 0x1.0p-53;
        vec3 w = v3_normalize(v3(0.3f, -0.5f, 0.8f));
        vec3 d = henyey_greenstein_sample(w, g, u1, u2);
        double mu = henyey_greenstein_sample_mu(g, u1);
        CHECK(fabs(v3_dot(d, w) - mu) < 1e-5 && fabs(v3_length(d) - 1.0) < 1e-5);
        s1 += mu;
        s2 += mu * mu;
    }
    double mean = s1 / n, var = s2 / n - mean * mean, se = sqrt(var / n);
    CHECK_NEAR(mean, g, 5.0 * se);
    double m2 = sphere_moment(henyey_greenstein_phase, g, 2);
    CHECK_NEAR(s2 / n, m2, 5.0 * sqrt(var / n) + 1e-9);
}

int main(void)
{
    CHECK_NEAR(sphere_moment(rayleigh2, 0.0, 0), 1.0, 1e-10);
    const double gs[] = {-0.6, 0.0, 0.3, 0.76, 0.9};
    for (int i = 0; i < 5; ++i) {
        double g = gs[i];
        CHECK_NEAR(sphere_moment(henyey_greenstein_phase, g, 0), 1.0, 1e-6);
        CHECK_NEAR(sphere_moment(henyey_greenstein_phase, g, 1), g, 1e-6);
        CHECK_NEAR(sphere_moment(cornette_shanks_phase, g, 0), 1.0, 1e-6);
        check_sampler(g);
    }
    CHECK_NEAR(henyey_greenstein_phase(0.4, 0.0), 1.0 / (4.0 * M_PI), 1e-15);
    CHECK_NEAR(cornette_shanks_phase(0.4, 0.0), rayleigh_phase(0.4), 1e-15); /* CS at g = 0 is Rayleigh */
    CHECK_NEAR(henyey_greenstein_sample_mu(0.5, 0.0), -1.0, 1e-12);
    CHECK_NEAR(henyey_greenstein_sample_mu(0.5, 1.0), 1.0, 1e-12);
    return check_report("test_phase_function");
}
