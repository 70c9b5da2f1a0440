#include "scene/material_lookup.h"

#include <math.h>
#include <stddef.h>

static float srgb_to_linear(float c)
{
    return c <= 0.04045f ? c / 12.92f : powf((c + 0.055f) / 1.055f, 2.4f);
}

static int wrap(int i, int n) { return ((i % n) + n) % n; }

/* A texture coordinate as the lookup takes it. Beyond 2^16, where REPEAT
 * makes whole periods irrelevant, only its fraction is kept (exactly: the
 * fraction of a float is a float), so pixel positions stay far inside int's
 * range for any texture gtlab loads (16384 texels a side at most); a
 * non-finite one (interpolated from huge ones) reads as 0. */
static float lookup_coordinate(float u)
{
    if (!isfinite(u))
        return 0.0f;
    return fabsf(u) < 65536.0f ? u : u - floorf(u);
}

/* Bilinear lookup of channel values (0..1) with REPEAT wrapping; glTF uv (0,0)
 * is the top-left of the image, the first row stored. */
static void texture_bilinear(const scene_texture *t, const float uv[2], float out[4])
{
    float x = lookup_coordinate(uv[0]) * (float)t->width - 0.5f, y = lookup_coordinate(uv[1]) * (float)t->height - 0.5f;
    float fx = floorf(x), fy = floorf(y);
    float wx = x - fx, wy = y - fy;
    int x0 = (int)fx, y0 = (int)fy;
    for (int c = 0; c < 4; ++c)
        out[c] = 0.0f;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            float w = (i ? wx : 1.0f - wx) * (j ? wy : 1.0f - wy);
            const unsigned char *texel =
                &t->rgba[4 * ((size_t)wrap(y0 + j, t->height) * (size_t)t->width + (size_t)wrap(x0 + i, t->width))];
            for (int c = 0; c < 4; ++c)
                out[c] += w * (float)texel[c] / 255.0f;
        }
    }
}

static const scene_texture *texture_at(const scene *s, int index)
{
    if (index < 0 || index >= s->texture_count || !s->textures[index].rgba)
        return NULL;
    return &s->textures[index];
}

material_sample material_lookup(const scene *s, int mesh, const float uv[2])
{
    const scene_material *m = scene_mesh_material(s, &s->meshes[mesh]);
    material_sample r;
    for (int c = 0; c < 3; ++c)
        r.base_color[c] = m->base_color[c];
    r.roughness = m->roughness;
    r.metallic = m->metallic;
    const scene_texture *color = texture_at(s, m->base_color_texture);
    if (color) {
        float texel[4];
        texture_bilinear(color, uv, texel);
        for (int c = 0; c < 3; ++c)
            r.base_color[c] *= srgb_to_linear(texel[c]);
    }
    const scene_texture *mr = texture_at(s, m->metallic_roughness_texture);
    if (mr) {
        float texel[4];
        texture_bilinear(mr, uv, texel);
        r.roughness *= texel[1];
        r.metallic *= texel[2];
    }
    return r;
}

int material_alpha_covers(const scene *s, int mesh, const float uv[2])
{
    int index = s->meshes[mesh].material;
    if (!s->alpha_cutoff || index < 0 || index >= s->material_count || s->alpha_cutoff[index] <= 0.0f)
        return 1;
    const scene_material *m = &s->materials[index];
    float alpha = m->base_color[3];
    const scene_texture *color = texture_at(s, m->base_color_texture);
    if (color) {
        float texel[4];
        texture_bilinear(color, uv, texel);
        alpha *= texel[3];
    }
    return alpha >= s->alpha_cutoff[index];
}
