/* The scene's content hash; see scene_hash.h. */
#include "scene/scene_hash.h"

#include <openssl/evp.h>
#include <stdio.h>

/* Lengths go in as 64-bit counts, so two layouts cannot hash alike. */
static int add(EVP_MD_CTX *ctx, const void *data, size_t size)
{
    uint64_t n = size;
    return EVP_DigestUpdate(ctx, &n, sizeof n) == 1 && (size == 0 || EVP_DigestUpdate(ctx, data, size) == 1) ? 0 : -1;
}

static int add_mesh(EVP_MD_CTX *ctx, const scene_mesh *m)
{
    const size_t v = m->vertex_count, t = m->triangle_count;
    const int flags[2] = {m->material, m->flat};
    return add(ctx, m->positions, 12 * v) | add(ctx, m->normals, 12 * v) |
           add(ctx, m->texcoords, m->texcoords ? 8 * v : 0) | add(ctx, m->indices, 12 * t) |
           add(ctx, flags, sizeof flags);
}

static int add_scene(EVP_MD_CTX *ctx, const scene *s)
{
    int rc = add(ctx, &s->mesh_count, sizeof s->mesh_count);
    for (int i = 0; i < s->mesh_count; ++i)
        rc |= add_mesh(ctx, &s->meshes[i]);
    rc |= add(ctx, s->materials, sizeof *s->materials * (size_t)s->material_count);
    if (s->alpha_cutoff) /* only then: an opaque scene's hash is what it always was */
        rc |= add(ctx, s->alpha_cutoff, sizeof *s->alpha_cutoff * (size_t)s->material_count);
    for (int i = 0; i < s->texture_count; ++i) {
        const scene_texture *t = &s->textures[i];
        const int size[2] = {t->width, t->height};
        rc |= add(ctx, size, sizeof size) | add(ctx, t->rgba, 4 * (size_t)t->width * (size_t)t->height);
    }
    return rc;
}

int scene_content_hash(const scene *s, char hex[SCENE_HASH_HEX])
{
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int size = 0;
    EVP_MD_CTX *ctx = EVP_MD_CTX_new();
    int ok = ctx && EVP_DigestInit_ex(ctx, EVP_sha256(), NULL) == 1 && add_scene(ctx, s) == 0 &&
             EVP_DigestFinal_ex(ctx, digest, &size) == 1 && size == 32;
    EVP_MD_CTX_free(ctx);
    for (unsigned int i = 0; ok && i < size; ++i)
        snprintf(hex + 2 * i, 3, "%02x", digest[i]);
    return ok ? 0 : -1;
}
