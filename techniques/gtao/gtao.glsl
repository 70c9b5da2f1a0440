#version 450
// GTAO (Jimenez et al. 2016) as gtlab runs it in C (techniques/gtao/gtao.c),
// under gtlab's screen-space contract (docs/shaders.md), in GLSL. The
// technique is gtao.inc beside this file, shared with gtao.hlsl; this file
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

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 0) uniform Gtlab
{
    vec4 camera_right, camera_up, camera_forward;
    float tan_half_yfov, aspect;
    int width, height;
    int frame, frames;
    int present, reserved;
};
layout(std140, binding = 1) uniform Params
{
    float radius, falloff, max_radius_px, slices, steps, thickness;
};
layout(std430, binding = 2) readonly buffer GBuffer { float gbuffer[]; };
layout(std430, binding = 3) writeonly buffer Outputs { float outputs[]; };

#define GTAO_CONST const
#include "gtao.inc"

void main() { gtao_pixel(int(gl_GlobalInvocationID.x), int(gl_GlobalInvocationID.y)); }
