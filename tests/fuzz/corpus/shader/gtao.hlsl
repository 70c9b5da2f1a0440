// GTAO (Jimenez et al. 2016) as gtlab runs it in C (techniques/gtao/gtao.c),
// under gtlab's screen-space contract (docs/shaders.md), in HLSL. The
// technique is gtao.inc beside this file, shared with gtao.glsl; this file
// holds only the bindings, the declarations and the dialect.
// techniques/shader/tests/test_gpu_screen_pass.c compares both with the C
// gtao_frame.
//
// gtlab.param radius 1.0
// gtlab.param falloff 0.25
// gtlab.param max_radius_px 256.0
// gtlab.param slices 4
// gtlab.param steps 8
// gtlab.param thickness 0.0
// gtlab.output ao.V

[[vk::binding(0)]] cbuffer Gtlab
{
    float4 camera_right, camera_up, camera_forward;
    float tan_half_yfov, aspect;
    int width, height;
    int frame, frames;
    int present, reserved;
};
[[vk::binding(1)]] cbuffer Params
{
    float radius, falloff, max_radius_px, slices, steps, thickness;
};
[[vk::binding(2)]] StructuredBuffer<float> gbuffer;
[[vk::binding(3)]] RWStructuredBuffer<float> outputs;

#define vec3 float3
#define GTAO_CONST static const
#include "gtao.inc"

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) { gtao_pixel(int(id.x), int(id.y)); }
