/* Phase functions; see phase_function.h for the formulas and sources. */
#include "core/optics/phase_function.h"

#include <math.h>

#include "core/frame.h"

double rayleigh_phase(double mu)
{
    return 3.0 / (16.0 * M_PI) * (1.0 + mu * mu);
}

double henyey_greenstein_phase(double mu, double g)
{
    double d = 1.0 + g * g - 2.0 * g * mu;
    return (1.0 - g * g) / (4.0 * M_PI * d * sqrt(d));
}

double cornette_shanks_phase(double mu, double g)
{
    double d = 1.0 + g * g - 2.0 * g * mu;
    return 3.0 / (8.0 * M_PI) * (1.0 - g * g) * (1.0 + mu * mu) / ((2.0 + g * g) * d * sqrt(d));
}

/* The inverse of the HG cumulative distribution in mu,
 * P(mu) = (1 - g^2) / (2 g) [ (1 + g^2 - 2 g mu)^(-1/2) - 1 / (1 + g) ]:
 * mu = (1 + g^2 - ((1 - g^2) / (1 - g + 2 g u))^2) / (2 g); near g = 0 the
 * isotropic limit mu = 1 - 2 u avoids the cancellation. */
double henyey_greenstein_sample_mu(double g, double u)
{
    if (fabs(g) < 1e-3)
        return 1.0 - 2.0 * u;
    double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
    double mu = (1.0 + g * g - s * s) / (2.0 * g);
    return fmax(-1.0, fmin(1.0, mu));
}

vec3 henyey_greenstein_sample(vec3 w, double g, double u1, double u2)
{
    double mu = henyey_greenstein_sample_mu(g, u1);
    double sin_theta = sqrt(fmax(0.0, 1.0 - mu * mu));
    double phi = 2.0 * M_PI * u2;
    frame f = frame_from_normal(w);
    return frame_to_world(&f, v3((float)(sin_theta * cos(phi)), (float)(sin_theta * sin(phi)), (float)mu));
}
