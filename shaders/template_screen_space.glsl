#version 450
// A screen-space shader under gtlab's contract (docs/shaders.md): copy it,
// keep the declarations, write main(). Run it with
//   gtlab shader run --shader my.glsl --gbuffer g.exr [--param strength=2] [--frames N] -o out.exr
//                    [--reference ao.exr --channel ao.V]
//
// Parameters: one float each, in the Params block in the order of these
// lines, with their defaults; --param NAME=VALUE replaces one.
// gtlab.param strength 1.0
// Outputs: one plane each, written to the EXR under these channel names.
// gtlab.output ao.V

layout(local_size_x = 8, local_size_y = 8) in; // the contract's workgroup: 8 x 8 pixels

// binding 0: gtlab's block. View space (realtime/screen_space.h): x right, y up,
// looking down -z; pixel (x, y) (y down) at depth d is d (sx, sy, -1) with
// sx = (2 (x + 0.5) / width - 1) tan_half_yfov aspect, sy = (1 - 2 (y + 0.5) / height) tan_half_yfov.
layout(std140, binding = 0) uniform Gtlab
{
    vec4 camera_right, camera_up, camera_forward; // world-space camera basis (w unused)
    float tan_half_yfov, aspect;
    int width, height;
    int frame, frames;  // this dispatch's frame, 0 .. frames-1 (the outputs are averaged)
    int present, reserved; // bit c: G-buffer plane c is in the EXR (else it is zeros)
};

// binding 1: the gtlab.param floats, in order.
layout(std140, binding = 1) uniform Params
{
    float strength;
};

// binding 2: the G-buffer, one plane of width x height floats per channel.
layout(std430, binding = 2) readonly buffer GBuffer { float gbuffer[]; };
const int DEPTH = 0;                     // depth.Z: distance along the camera axis
const int N_X = 1, N_Y = 2, N_Z = 3;     // N: world-space shading normal
const int P_X = 4, P_Y = 5, P_Z = 6;     // P: world-space position
const int ALBEDO_R = 7, ALBEDO_G = 8, ALBEDO_B = 9;
const int ROUGHNESS = 10;                // roughness.Y: perceptual
const int MASK = 11;                     // mask.A: 1 where a surface was hit
const int BENT_X = 12, BENT_Y = 13, BENT_Z = 14; // the AO reference's bent normal
float channel(int c, int x, int y) { return gbuffer[(c * height + y) * width + x]; }

// binding 3: the outputs, one plane per gtlab.output line.
layout(std430, binding = 3) writeonly buffer Outputs { float outputs[]; };
void write_output(int k, int x, int y, float value) { outputs[(k * height + y) * width + x] = value; }

void main()
{
    int x = int(gl_GlobalInvocationID.x), y = int(gl_GlobalInvocationID.y);
    if (x >= width || y >= height)
        return;
    // An example: the normal's facing towards the camera, scaled.
    vec3 n = vec3(channel(N_X, x, y), channel(N_Y, x, y), channel(N_Z, x, y));
    float facing = clamp(-dot(n, camera_forward.xyz), 0.0, 1.0);
    write_output(0, x, y, channel(MASK, x, y) != 0.0 ? min(strength * facing, 1.0) : 0.0);
}
