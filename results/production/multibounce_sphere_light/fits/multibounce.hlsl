// GTAO multi-bounce, refitted by gtlab 0.1.0:
//   gtlab all --quality production
// Same form as GTAOMultiBounce (Jimenez et al. 2016), new coefficients. Generated file.

// a, b, c linear in the albedo (the talk's form); weighted RMSE 0.0323 on the data.
float3 GTAOMultiBounce(float visibility, float3 albedo)
{
    float3 a = -0.413111997f + albedo * (2.37885216f);
    float3 b = 0.760794536f + albedo * (-5.3097785f);
    float3 c = 0.648186513f + albedo * (2.93806436f);
    float x = visibility;
    return max(((x * a + b) * x + c) * x, x);
}

// a, b, c quadratic in the albedo; weighted RMSE 0.0304 on the data.
float3 GTAOMultiBounceQuadratic(float visibility, float3 albedo)
{
    float3 a = 0.118085038f + albedo * (-0.59059538f + albedo * (2.96589621f));
    float3 b = -0.202320504f + albedo * (0.0741359817f + albedo * (-5.37747535f));
    float3 c = 1.08520042f + albedo * (0.49511082f + albedo * (2.44003169f));
    float x = visibility;
    return max(((x * a + b) * x + c) * x, x);
}

// anchored: V_d + V_d (1 - V_d) (albedo (p1 + q1 V_d) + albedo^2 (p2 + q2 V_d)), exact at albedo 0 and V_d = 0, 1; weighted RMSE 0.0304 on the data. Preferred by the leave-one-scene-out test.
float3 GTAOMultiBounceAnchored(float visibility, float3 albedo)
{
    float3 a = 0.0f + albedo * (0.0717112256f + albedo * (2.30077099f));
    float3 b = 0.0f + albedo * (-0.986918909f + albedo * (-4.34434018f));
    float3 c = 1.0f + albedo * (0.915207683f + albedo * (2.04356919f));
    float x = visibility;
    return max(((x * a + b) * x + c) * x, x);
}
