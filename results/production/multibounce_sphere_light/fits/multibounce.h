/* GTAO multi-bounce, refitted by gtlab 0.1.0:
 *   gtlab all --quality production
 * V'_d = max(V_d, ((a V_d + b) V_d + c) V_d) with a, b, c polynomials in the albedo
 * (Jimenez et al. 2016). Generated file: edit the data, not the numbers. */
#ifndef GTLAB_MULTIBOUNCE_FIT_H
#define GTLAB_MULTIBOUNCE_FIT_H

/* a, b, c linear in the albedo (the talk's form); weighted RMSE 0.0323 on the data. */
static inline float gtlab_multibounce_linear(float visibility, float albedo)
{
    float a = -0.413111997f + albedo * (2.37885216f);
    float b = 0.760794536f + albedo * (-5.3097785f);
    float c = 0.648186513f + albedo * (2.93806436f);
    float x = visibility, y = ((a * x + b) * x + c) * x;
    return y > x ? y : x;
}

/* a, b, c quadratic in the albedo; weighted RMSE 0.0304 on the data. */
static inline float gtlab_multibounce_quadratic(float visibility, float albedo)
{
    float a = 0.118085038f + albedo * (-0.59059538f + albedo * (2.96589621f));
    float b = -0.202320504f + albedo * (0.0741359817f + albedo * (-5.37747535f));
    float c = 1.08520042f + albedo * (0.49511082f + albedo * (2.44003169f));
    float x = visibility, y = ((a * x + b) * x + c) * x;
    return y > x ? y : x;
}

/* anchored: V_d + V_d (1 - V_d) (albedo (p1 + q1 V_d) + albedo^2 (p2 + q2 V_d)), exact at albedo 0 and V_d = 0, 1; weighted RMSE 0.0304 on the data. Preferred by the leave-one-scene-out test. */
static inline float gtlab_multibounce_anchored(float visibility, float albedo)
{
    float a = 0.0f + albedo * (0.0717112256f + albedo * (2.30077099f));
    float b = 0.0f + albedo * (-0.986918909f + albedo * (-4.34434018f));
    float c = 1.0f + albedo * (0.915207683f + albedo * (2.04356919f));
    float x = visibility, y = ((a * x + b) * x + c) * x;
    return y > x ? y : x;
}

#endif
