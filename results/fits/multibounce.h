/* GTAO multi-bounce, refitted by gtlab 0.1.0:
 *   gtlab all --quality preview
 * V'_d = max(V_d, ((a V_d + b) V_d + c) V_d) with a, b, c polynomials in the albedo
 * (Jimenez et al. 2016). Generated file: edit the data, not the numbers. */
#ifndef GTLAB_MULTIBOUNCE_FIT_H
#define GTLAB_MULTIBOUNCE_FIT_H

/* a, b, c linear in the albedo (the talk's form); weighted RMSE 0.0341 on the data. */
static inline float gtlab_multibounce_linear(float visibility, float albedo)
{
    float a = -0.410470316f + albedo * (2.36853008f);
    float b = 0.756915933f + albedo * (-5.29483633f);
    float c = 0.649498611f + albedo * (2.93318053f);
    float x = visibility, y = ((a * x + b) * x + c) * x;
    return y > x ? y : x;
}

/* a, b, c quadratic in the albedo; weighted RMSE 0.0323 on the data. */
static inline float gtlab_multibounce_quadratic(float visibility, float albedo)
{
    float a = 0.117244771f + albedo * (-0.581452996f + albedo * (2.94645501f));
    float b = -0.201069571f + albedo * (0.060403477f + albedo * (-5.34883497f));
    float c = 1.08477146f + albedo * (0.499959653f + albedo * (2.43031066f));
    float x = visibility, y = ((a * x + b) * x + c) * x;
    return y > x ? y : x;
}

/* anchored: V_d + V_d (1 - V_d) (albedo (p1 + q1 V_d) + albedo^2 (p2 + q2 V_d)), exact at albedo 0 and V_d = 0, 1; weighted RMSE 0.0324 on the data. Preferred by the leave-one-scene-out test. */
static inline float gtlab_multibounce_anchored(float visibility, float albedo)
{
    float a = 0.0f + albedo * (0.0745902776f + albedo * (2.28996659f));
    float b = 0.0f + albedo * (-0.991776622f + albedo * (-4.32745444f));
    float c = 1.0f + albedo * (0.917186344f + albedo * (2.03748785f));
    float x = visibility, y = ((a * x + b) * x + c) * x;
    return y > x ? y : x;
}

#endif
