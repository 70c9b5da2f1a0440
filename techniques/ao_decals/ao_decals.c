/* INSIDE's AO decals and the exact occlusions they approximate: see ao_decals.h. */
#include "ao_decals/ao_decals.h"

#include <math.h>

#include "realtime/sphere_illuminance.h"

float ao_point_decal_published(vec3 pos, vec3 norm)
{
    float n_dot_l = v3_dot(v3_normalize(pos), norm) * 0.5f + 0.5f;
    float falloff = fmaxf(0.0f, 1.0f - v3_length(pos));
    return falloff * falloff * n_dot_l;
}

float ao_point_decal(vec3 pos, vec3 norm, float exponent, float wrap)
{
    float n_dot_l = fmaxf(0.0f, (v3_dot(v3_normalize(pos), norm) + wrap) / (1.0f + wrap));
    return powf(fmaxf(0.0f, 1.0f - v3_length(pos)), exponent) * n_dot_l;
}

void ao_decal_unit_space(vec3 p, vec3 n, const ao_decal_volume *v, vec3 *pos, vec3 *norm)
{
    vec3 d = v3_sub(p, v->centre);
    *pos = v3(d.x / v->half.x, d.y / v->half.y, d.z / v->half.z);
    *norm = v3_normalize(v3(n.x * v->half.x, n.y * v->half.y, n.z * v->half.z));
}

float ao_sphere_quilez(vec3 p, vec3 n, vec3 centre, float radius)
{
    vec3 d = v3_sub(centre, p);
    float l = v3_length(d);
    return fminf(1.0f, fmaxf(0.0f, v3_dot(n, d) / l * (radius / l) * (radius / l)));
}

float ao_sphere_exact(vec3 p, vec3 n, vec3 centre, float radius)
{
    vec3 d = v3_sub(centre, p);
    float l = v3_length(d);
    return sphere_illuminance_frostbite(v3_dot(n, d) / l, radius / l) / (float)M_PI;
}

typedef struct {
    double x, y, z;
} dvec;

static dvec dv(vec3 a) { return (dvec){a.x, a.y, a.z}; }
static dvec dsub(dvec a, dvec b) { return (dvec){a.x - b.x, a.y - b.y, a.z - b.z}; }
static double ddot(dvec a, dvec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static dvec dcross(dvec a, dvec b) { return (dvec){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
static dvec dlerp(dvec a, dvec b, double t) { return (dvec){a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)}; }

/* Sutherland-Hodgman against n.x > 0 (x relative to p); returns the new count. Strict, so that a
 * polygon lying in the tangent plane (a wall through p: it subtends no projected solid angle) is
 * clipped away instead of being counted as the whole horizon disc; a vertex on the plane is still
 * kept as the crossing point of its edge to an upper vertex. */
static int clip_to_horizon(const dvec *in, int count, dvec n, dvec *out)
{
    int m = 0;
    for (int i = 0; i < count; ++i) {
        dvec a = in[i], b = in[(i + 1) % count];
        double da = ddot(n, a), db = ddot(n, b);
        if (da > 0.0)
            out[m++] = a;
        if ((da > 0.0) != (db > 0.0))
            out[m++] = dlerp(a, b, da / (da - db));
    }
    return m;
}

double ao_polygon_form_factor(vec3 p, vec3 n, const vec3 *vertices, int count)
{
    dvec rel[8], clipped[16], dn = dv(n);
    for (int i = 0; i < count && i < 8; ++i)
        rel[i] = dsub(dv(vertices[i]), dv(p));
    int m = clip_to_horizon(rel, count < 8 ? count : 8, dn, clipped);
    double sum = 0.0;
    for (int i = 0; i < m; ++i) {
        dvec a = clipped[i], b = clipped[(i + 1) % m], c = dcross(a, b);
        double la = sqrt(ddot(a, a)), lb = sqrt(ddot(b, b)), lc = sqrt(ddot(c, c));
        if (la <= 0.0 || lb <= 0.0 || lc <= 0.0)
            continue;
        sum += atan2(lc, ddot(a, b)) * ddot(dn, c) / lc;
    }
    return fabs(sum) / (2.0 * M_PI);
}

/* Face f (axis f / 2, side f % 2) of the box as 4 corners. */
static void box_face(vec3 lo, vec3 hi, int f, vec3 quad[4])
{
    int axis = f / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
    float c[3][2] = {{lo.x, hi.x}, {lo.y, hi.y}, {lo.z, hi.z}};
    static const int corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 4; ++k) {
        float xyz[3];
        xyz[axis] = c[axis][f % 2], xyz[u] = c[u][corner[k][0]], xyz[v] = c[v][corner[k][1]];
        quad[k] = v3(xyz[0], xyz[1], xyz[2]);
    }
}

double ao_box_exact(vec3 p, vec3 n, vec3 lo, vec3 hi)
{
    float pc[3] = {p.x, p.y, p.z}, l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
    double a = 0.0;
    for (int f = 0; f < 6; ++f) {
        int axis = f / 2;
        if (f % 2 ? pc[axis] <= h[axis] : pc[axis] >= l[axis])
            continue; /* the face looks away from p */
        vec3 quad[4];
        box_face(lo, hi, f, quad);
        a += ao_polygon_form_factor(p, n, quad, 4);
    }
    return a;
}
