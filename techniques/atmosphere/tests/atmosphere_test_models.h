/* Atmospheres the atmosphere tests share. */
#ifndef GTLAB_ATMOSPHERE_TESTS_TEST_MODELS_H
#define GTLAB_ATMOSPHERE_TESTS_TEST_MODELS_H

#include "atmosphere/atmosphere_model.h"

/* The default atmosphere with scale heights of 1e13 m: every species'
 * density is constant over the shell (to 1e-8), so transmittance and
 * single scattering have closed forms. */
static inline atmosphere_model atmosphere_model_homogeneous(void)
{
    atmosphere_model m = atmosphere_model_default();
    for (int w = 0; w < ATMOSPHERE_WEATHERS; ++w)
        m.weathers[w].rayleigh_scale_height = m.weathers[w].mie_scale_height = 1e13;
    return m;
}

#endif
