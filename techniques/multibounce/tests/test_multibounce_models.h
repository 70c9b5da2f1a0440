/* The multi-bounce models the shader tests generate code for: the talk's
 * (linear in the albedo), a quadratic one and the anchored form
 * (multibounce/multibounce.h). Shared by test_multibounce_shader.c (the C,
 * C header and shader text) and test_multibounce_gpu.c (the shaders run on
 * Vulkan) beside it. */
#ifndef GTLAB_MULTIBOUNCE_TESTS_TEST_MULTIBOUNCE_MODELS_H
#define GTLAB_MULTIBOUNCE_TESTS_TEST_MULTIBOUNCE_MODELS_H

#include "multibounce/multibounce.h"

enum { TEST_MULTIBOUNCE_MODELS = 3 };

static inline void test_multibounce_models(multibounce_model m[TEST_MULTIBOUNCE_MODELS])
{
    static const double anchored[MULTIBOUNCE_ANCHORED_PARAMETERS] = {1.55525552, -1.02759191, 1.84048654, -1.96829179};
    m[0] = multibounce_model_jimenez2016();
    m[1] = (multibounce_model){.degree = 2,
                               .a = {0.0577464678, 0.713961848, 2.29879408},
                               .b = {-0.102705944, -2.06036548, -4.33118267},
                               .c = {1.0453124, 1.33703475, 2.04820687}};
    m[2] = multibounce_model_anchored(anchored);
}

#endif
