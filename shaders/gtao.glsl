#version 450
// GTAO (Jimenez et al. 2016) as gtlab runs it in C (realtime/gtao.c), ported
// to GLSL under gtlab's screen-space contract (docs/shaders.md): one
// configuration, the one tests/gpu/test_gpu_screen_pass.c compares with the C
// gtao_frame: cosine weighting, regular slices (no spatio-temporal pattern,
// step offset 0.5), exact acos, no denoiser, no bent normal. Every function is
// the C function of the same name; `precise` keeps the compiler from fusing
// multiply-adds where the C rounds twice (-ffp-contract=off), so the samples
// land where the C's do.
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

const int DEPTH = 0, N_X = 1, MASK = 11;
const float PI = 3.14159265358979;
const float HEIGHTFIELD_MIN_FACING = 1e-3;

float channel(int c, int x, int y) { return gbuffer[c * width * height + y * width + x]; }

bool covered(int x, int y)
{
    return x >= 0 && y >= 0 && x < width && y < height && channel(MASK, x, y) != 0.0;
}

precise vec3 view_position(int x, int y)
{
    precise float d = channel(DEPTH, x, y);
    precise float sx = (2.0 * (float(x) + 0.5) / float(width) - 1.0) * tan_half_yfov * aspect;
    precise float sy = (1.0 - 2.0 * (float(y) + 0.5) / float(height)) * tan_half_yfov;
    return vec3(sx * d, sy * d, -d);
}

precise vec3 view_normal(int x, int y)
{
    vec3 n = vec3(channel(N_X, x, y), channel(N_X + 1, x, y), channel(N_X + 2, x, y));
    return vec3(dot(n, camera_right.xyz), dot(n, camera_up.xyz), -dot(n, camera_forward.xyz));
}

// The tangent plane of the pixel the point falls in, clamped to the depths
// of the pixel and its 8 neighbours (core/heightfield_model.h).
precise vec3 sample_position(float fx, float fy)
{
    int x = int(floor(fx)), y = int(floor(fy));
    precise vec3 w = vec3((2.0 * fx / float(width) - 1.0) * tan_half_yfov * aspect,
                          (1.0 - 2.0 * fy / float(height)) * tan_half_yfov, -1.0);
    precise vec3 p = view_position(x, y), n = view_normal(x, y);
    precise float nw = dot(n, w), depth = dot(n, p) / nw;
    if (!(abs(nw) >= HEIGHTFIELD_MIN_FACING * length(w) && depth > 0.0))
        depth = -p.z;
    float lo = -p.z, hi = -p.z;
    for (int k = 0; k < 9; ++k) {
        int ox = k % 3 - 1, oy = k / 3 - 1;
        float d;
        if (covered(x + ox, y + oy))
            d = channel(DEPTH, x + ox, y + oy);
        else if (covered(x - ox, y - oy))
            d = -2.0 * p.z - channel(DEPTH, x - ox, y - oy);
        else
            continue;
        lo = min(lo, d);
        hi = max(hi, d);
    }
    return w * clamp(depth, lo, hi);
}

float radius_px(int x, int y)
{
    precise float pixels_per_unit = 0.5 * float(height) / (tan_half_yfov * channel(DEPTH, x, y));
    return min(radius * pixels_per_unit, max_radius_px);
}

float attenuation(float distance)
{
    float fade = falloff * radius;
    if (fade <= 0.0)
        return distance <= radius ? 1.0 : 0.0;
    return min(max((radius - distance) / fade, 0.0), 1.0);
}

// Cosine of one side's horizon from the samples at radius_px (j + 0.5) / steps.
float side_horizon_cos(int x, int y, vec3 pc, vec3 v, float dx, float dy, float r, float low)
{
    float horizon = low;
    for (int j = 0; j < int(steps); ++j) {
        precise float t = r * (float(j) + 0.5) / steps;
        precise float fx = float(x) + 0.5 + t * dx, fy = float(y) + 0.5 + t * dy;
        int sx = int(floor(fx)), sy = int(floor(fy));
        if ((sx == x && sy == y) || !covered(sx, sy))
            continue;
        vec3 d = sample_position(fx, fy) - pc;
        float len = length(d);
        float c = low + attenuation(len) * (dot(d, v) / len - low);
        if (c > horizon)
            horizon = c;
        else
            horizon += thickness * (max(c, low) - horizon);
    }
    return horizon;
}

float integrate_arc_cosine(float h1, float h2, float n)
{
    float cos_n = cos(n), sin_n = sin(n);
    return 0.25 * (-cos(2.0 * h1 - n) + cos_n + 2.0 * h1 * sin_n) + 0.25 * (-cos(2.0 * h2 - n) + cos_n + 2.0 * h2 * sin_n);
}

// One slice's weighted visibility (gtao_search_slice, gtao_slice_weight, slice_visibility).
float slice_visibility(int x, int y, float phi)
{
    vec3 pc = view_position(x, y), n = view_normal(x, y);
    float dx = cos(phi), dy = sin(phi);
    vec3 d3 = vec3(dx, -dy, 0.0);
    vec3 v = normalize(-pc);
    vec3 side = normalize(d3 - v * dot(d3, v));
    float dv = dx * v.x - dy * v.y;
    float weight = v.z / (1.0 - dv * dv);
    vec3 axis = cross(side, v);
    vec3 np = n - axis * dot(n, axis);
    float n_len = length(np);
    float cos_n = n_len > 0.0 ? dot(np, v) / n_len : 1.0;
    float n_angle = acos(clamp(cos_n, -1.0, 1.0));
    float na = dot(np, side) < 0.0 ? -n_angle : n_angle;
    float sin_n = sin(na);
    float r = radius_px(x, y);
    float c2 = side_horizon_cos(x, y, pc, v, dx, dy, r, -sin_n);
    float c1 = side_horizon_cos(x, y, pc, v, -dx, -dy, r, sin_n);
    float h1 = -acos(clamp(c1, -1.0, 1.0)), h2 = acos(clamp(c2, -1.0, 1.0));
    h1 = na + max(h1 - na, -0.5 * PI);
    h2 = na + min(h2 - na, 0.5 * PI);
    return weight * n_len * integrate_arc_cosine(h1, h2, na);
}

void main()
{
    int x = int(gl_GlobalInvocationID.x), y = int(gl_GlobalInvocationID.y);
    if (x >= width || y >= height)
        return;
    float sum = 0.0;
    if (channel(MASK, x, y) != 0.0)
        for (int k = 0; k < int(slices); ++k)
            sum += slice_visibility(x, y, PI * (float(k) + 0.5) / slices);
    outputs[y * width + x] = channel(MASK, x, y) != 0.0 ? sum / slices : 0.0;
}
