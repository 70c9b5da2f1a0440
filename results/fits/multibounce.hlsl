// GTAO multi-bounce, refitted by gtlab 0.1.0:
//   gtlab all --quality preview
// Same form as GTAOMultiBounce (Jimenez et al. 2016), new coefficients. Generated file.

// a, b, c linear in the albedo (the talk's form); weighted RMSE 0.0341 on the data.
float3 GTAOMultiBounce(float visibility, float3 albedo)
{
    float3 a = -0.410470316f + albedo * (2.36853008f);
    float3 b = 0.756915933f + albedo * (-5.29483633f);
    float3 c = 0.649498611f + albedo * (2.93318053f);
    float x = visibility;
    return max(((x * a + b) * x + c) * x, x);
}

// a, b, c quadratic in the albedo; weighted RMSE 0.0323 on the data.
float3 GTAOMultiBounceQuadratic(float visibility, float3 albedo)
{
    float3 a = 0.117244771f + albedo * (-0.581452996f + albedo * (2.94645501f));
    float3 b = -0.201069571f + albedo * (0.060403477f + albedo * (-5.34883497f));
    float3 c = 1.08477146f + albedo * (0.499959653f + albedo * (2.43031066f));
    float x = visibility;
    return max(((x * a + b) * x + c) * x, x);
}

// anchored: V_d + V_d (1 - V_d) (albedo (p1 + q1 V_d) + albedo^2 (p2 + q2 V_d)), exact at albedo 0 and V_d = 0, 1; weighted RMSE 0.0324 on the data. Preferred by the leave-one-scene-out test.
float3 GTAOMultiBounceAnchored(float visibility, float3 albedo)
{
    float3 a = 0.0f + albedo * (0.0745902776f + albedo * (2.28996659f));
    float3 b = 0.0f + albedo * (-0.991776622f + albedo * (-4.32745444f));
    float3 c = 1.0f + albedo * (0.917186344f + albedo * (2.03748785f));
    float x = visibility;
    return max(((x * a + b) * x + c) * x, x);
}
