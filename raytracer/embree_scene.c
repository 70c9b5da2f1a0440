#include "raytracer/embree_scene.h"

#include "raytracer/embree_memory.h"
#include "scene/material_lookup.h"

#include <float.h>
#include <math.h>
#include <string.h>

static void report_embree_error(void *user, enum RTCError code, const char *message)
{
    (void)user;
    (void)code;
    (void)message; /* surfaced through rtcGetDeviceError where it matters */
}

static void alpha_filter(const struct RTCFilterFunctionNArguments *args);

static int add_mesh(embree_scene *es, const scene_mesh *m, unsigned id, gt_error *e)
{
    RTCGeometry g = rtcNewGeometry(es->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    float *vertices = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                              m->vertex_count);
    unsigned *indices = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                m->triangle_count);
    if (!vertices || !indices) {
        rtcReleaseGeometry(g);
        return gt_error_set(e, "embree", "cannot allocate geometry buffers for mesh %u", id);
    }
    memcpy(vertices, m->positions, sizeof(float) * 3 * m->vertex_count);
    memcpy(indices, m->indices, sizeof(unsigned) * 3 * m->triangle_count);
    const float *cutoff = es->source->alpha_cutoff;
    if (cutoff && m->material >= 0 && m->material < es->source->material_count && cutoff[m->material] > 0.0f) {
        rtcSetGeometryUserData(g, (void *)es->source);
        rtcSetGeometryIntersectFilterFunction(g, alpha_filter);
        rtcSetGeometryOccludedFilterFunction(g, alpha_filter);
    }
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(es->rtc, g, id);
    rtcReleaseGeometry(g);
    return 0;
}

static uint64_t triangle_total(const scene *s)
{
    uint64_t n = 0;
    for (int i = 0; i < s->mesh_count; ++i)
        n += s->meshes[i].triangle_count;
    return n;
}

int embree_scene_build(const scene *s, embree_scene *es, gt_error *e)
{
    memset(es, 0, sizeof *es);
    uint64_t triangles = triangle_total(s);
    if (embree_check_memory(s->name, triangles, memory_available_bytes(), e) != 0)
        return -1;
    es->source = s;
    es->device = rtcNewDevice(NULL);
    if (!es->device)
        return gt_error_set(e, "embree", "cannot create a device: %s", embree_error_name(rtcGetDeviceError(NULL)));
    rtcSetDeviceErrorFunction(es->device, report_embree_error, NULL);
    es->rtc = rtcNewScene(es->device);
    rtcSetSceneFlags(es->rtc, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(es->rtc, RTC_BUILD_QUALITY_HIGH);
    for (int i = 0; i < s->mesh_count; ++i) {
        if (s->meshes[i].triangle_count == 0)
            continue;
        if (add_mesh(es, &s->meshes[i], (unsigned)i, e) != 0) {
            embree_scene_release(es);
            return -1;
        }
    }
    rtcCommitScene(es->rtc);
    enum RTCError err = rtcGetDeviceError(es->device);
    if (err != RTC_ERROR_NONE) {
        embree_scene_release(es);
        return gt_error_set(e, s->name, "Embree could not build the scene of %llu triangles: %s%s", (unsigned long long)triangles,
                            embree_error_name(err), err == RTC_ERROR_OUT_OF_MEMORY ? " (simplify the scene or use a machine with more memory)" : "");
    }
    return 0;
}

void embree_scene_release(embree_scene *es)
{
    if (es->rtc)
        rtcReleaseScene(es->rtc);
    if (es->device)
        rtcReleaseDevice(es->device);
    memset(es, 0, sizeof *es);
}

static vec3 barycentric_vec3(const float *data, const uint32_t *tri, float u, float v)
{
    vec3 a = v3_load(&data[3 * tri[0]]), b = v3_load(&data[3 * tri[1]]), c = v3_load(&data[3 * tri[2]]);
    return v3_add(v3_scale(a, 1.0f - u - v), v3_add(v3_scale(b, u), v3_scale(c, v)));
}

/* The shading normal interpolated from the vertices, unit, on ng's side (ng
 * where the interpolation vanishes). */
static vec3 shading_normal(const scene_mesh *m, const uint32_t *tri, float u, float v, vec3 ng)
{
    vec3 ns = barycentric_vec3(m->normals, tri, u, v);
    float ns_len = v3_length(ns);
    ns = ns_len > 0.0f ? v3_scale(ns, 1.0f / ns_len) : ng;
    return v3_dot(ns, ng) < 0.0f ? v3_neg(ns) : ns;
}

static void texcoords(const scene_mesh *m, const uint32_t *tri, float u, float v, float uv[2])
{
    uv[0] = uv[1] = 0.0f;
    if (!m->texcoords)
        return;
    const float *t0 = &m->texcoords[2 * tri[0]], *t1 = &m->texcoords[2 * tri[1]], *t2 = &m->texcoords[2 * tri[2]];
    for (int k = 0; k < 2; ++k)
        uv[k] = (1.0f - u - v) * t0[k] + u * t1[k] + v * t2[k];
}

/* glTF alpha coverage (alphaMode MASK) as an Embree filter function on the
 * alpha-tested meshes, for closest hits and occlusion alike: a candidate hit
 * whose alpha at its TEXCOORD_0 (barycentric interpolation, as
 * embree_surface_at) is below the cutoff is refused and the ray goes on. */
static void alpha_filter(const struct RTCFilterFunctionNArguments *args)
{
    const scene *s = args->geometryUserPtr;
    const unsigned n = args->N;
    const float *hit_f = (const float *)args->hit; /* RTCHitN: Ng x, y, z, u, v, primID, geomID, N each */
    const unsigned *hit_u = (const unsigned *)args->hit;
    for (unsigned k = 0; k < n; ++k) {
        if (args->valid[k] != -1)
            continue;
        unsigned tri = hit_u[5 * n + k], mesh = hit_u[6 * n + k];
        float uv[2];
        texcoords(&s->meshes[mesh], &s->meshes[mesh].indices[3 * tri], hit_f[3 * n + k], hit_f[4 * n + k], uv);
        if (!material_alpha_covers(s, (int)mesh, uv))
            args->valid[k] = 0;
    }
}

void embree_surface_at(const embree_scene *es, const struct RTCRayHit *rh, unsigned parts, surface_hit *hit)
{
    const scene_mesh *m = &es->source->meshes[rh->hit.geomID];
    const uint32_t *tri = &m->indices[3 * rh->hit.primID];
    float u = rh->hit.u, v = rh->hit.v;
    hit->mesh = (int)rh->hit.geomID;
    hit->triangle = (int)rh->hit.primID;
    hit->t = rh->ray.tfar;
    hit->p = barycentric_vec3(m->positions, tri, u, v);
    vec3 ng = v3_normalize(v3(rh->hit.Ng_x, rh->hit.Ng_y, rh->hit.Ng_z));
    if (v3_dot(ng, v3(rh->ray.dir_x, rh->ray.dir_y, rh->ray.dir_z)) > 0.0f)
        ng = v3_neg(ng);
    hit->ng = ng;
    hit->ns = parts & SURFACE_SHADING_NORMAL ? shading_normal(m, tri, u, v, ng) : ng;
    hit->uv[0] = hit->uv[1] = 0.0f;
    if (parts & SURFACE_TEXCOORDS)
        texcoords(m, tri, u, v, hit->uv);
}

int embree_closest_hit(const embree_scene *es, vec3 o, vec3 d, float t_max, surface_hit *hit)
{
    struct RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    struct RTCRayHit rh;
    embree_ray_init(&rh.ray, o, d, t_max);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(es->rtc, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
        return 0;
    embree_surface_at(es, &rh, SURFACE_ALL, hit);
    return 1;
}

void embree_closest_hit_stream(const embree_scene *es, struct RTCRayHit *rays, unsigned count)
{
    if (count == 0)
        return;
    for (unsigned i = 0; i < count; ++i) {
        rays[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rays[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    }
    struct RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    rtcIntersect1M(es->rtc, &context, rays, count, sizeof(struct RTCRayHit));
}

vec3 offset_ray_origin(vec3 p, vec3 ng)
{
    /* Barycentric interpolation of float vertices is accurate to a few ulps of
     * the largest coordinate (pbrt-v4 3.9.x); 32 ulps at that magnitude is
     * safely above it and still sub-micron for scenes of metre scale. */
    float offset = 32.0f * FLT_EPSILON * (1.0f + v3_max_abs_component(p));
    return v3_add(p, v3_scale(ng, offset));
}

void embree_unoccluded_stream(const embree_scene *es, struct RTCRay *rays, unsigned count)
{
    if (count == 0)
        return;
    struct RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    rtcOccluded1M(es->rtc, &context, rays, count, sizeof(struct RTCRay));
}
