// gtlab's per-sample function contract (docs/shaders.md, "Functions"):
// write only this function; gtlab wraps it into a compute shader, runs it on
// Vulkan over the multi-bounce references' samples and scores it like its own
// variants:  gtlab shader score --function template_multibounce.hlsl REF.exr ...
// The file is used as written, gtlab's wrapper after it. Helpers may precede
// the function; names starting gtlab_ are gtlab's.
//
// V'_d, the visibility with inter-reflections, from the ambient visibility
// V_d and one colour channel's albedo. This one is GTAOMultiBounce with the
// talk's coefficients (Jimenez et al. 2016, "Practical Real-Time Strategies
// for Accurate Indirect Occlusion", "Shader Code").
float gtlab_multibounce(float visibility, float albedo)
{
    float a = 2.0404 * albedo - 0.3324;
    float b = -4.7951 * albedo + 0.6417;
    float c = 2.7552 * albedo + 0.6903;
    float x = visibility;
    return max(x, ((x * a + b) * x + c) * x);
}
