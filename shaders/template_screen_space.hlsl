// The HLSL form of shaders/template_screen_space.glsl (docs/shaders.md): the
// same bindings through [[vk::binding(N)]], entry point main (or --entry).
// gtlab.param strength 1.0
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
    float strength;
};
[[vk::binding(2)]] StructuredBuffer<float> gbuffer;
[[vk::binding(3)]] RWStructuredBuffer<float> outputs;

static const int N_X = 1, N_Y = 2, N_Z = 3, MASK = 11;
float channel(int c, int x, int y) { return gbuffer[(c * height + y) * width + x]; }

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    int x = int(id.x), y = int(id.y);
    if (x >= width || y >= height)
        return;
    float3 n = float3(channel(N_X, x, y), channel(N_Y, x, y), channel(N_Z, x, y));
    float facing = saturate(-dot(n, camera_forward.xyz));
    outputs[y * width + x] = channel(MASK, x, y) != 0.0 ? min(strength * facing, 1.0) : 0.0;
}
