/* The glTF reader's shared parts (scene/gltf/gltf_reader.h is the C interface):
 * internal to the C++ adapter, which is split by concept into
 * gltf_reader.cpp (parsing, the node tree, materials, the public entry
 * points), gltf_accessors.cpp (accessor data: views, sparse substitution,
 * component types, extension values, meshopt-compressed views) and
 * gltf_primitive.cpp (a primitive's geometry: topology, Draco, morph targets,
 * skins, node transforms), over gltf_names.cpp (values in words, range
 * checks); each file calls only the ones listed after it. Only those files
 * include it. */
#ifndef GTLAB_SCENE_GLTF_GLTF_LOADER_HPP
#define GTLAB_SCENE_GLTF_GLTF_LOADER_HPP

#include <tiny_gltf.h>

#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <vector>

extern "C" {
#include "core/error.h"
#include "core/vec3.h"
#include "scene/gltf/gltf_reader.h"
#include "scene/gltf/uv_transform.h"
}

namespace gltf_detail {

/* ---------------------------------------------------------------- matrices */

/* 4x4 affine transform, column-major as glTF stores it: m[4 * column + row]. */
struct Mat4 {
    double m[16];
};

inline Mat4 mat4_identity()
{
    Mat4 r = {{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};
    return r;
}

inline Mat4 mat4_mul(const Mat4 &a, const Mat4 &b)
{
    Mat4 r;
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row) {
            double sum = 0.0;
            for (int k = 0; k < 4; ++k)
                sum += a.m[4 * k + row] * b.m[4 * c + k];
            r.m[4 * c + row] = sum;
        }
    return r;
}

/* T * R * S (glTF 2.0 "Transformations"), R from the unit quaternion (x, y, z, w). */
inline Mat4 mat4_trs(const double t[3], const double q[4], const double s[3])
{
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double rot[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                              {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                              {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    Mat4 r = mat4_identity();
    for (int c = 0; c < 3; ++c)
        for (int row = 0; row < 3; ++row)
            r.m[4 * c + row] = rot[row][c] * s[c];
    for (int row = 0; row < 3; ++row)
        r.m[12 + row] = t[row];
    return r;
}

inline vec3 mat4_point(const Mat4 &a, const float p[3])
{
    double r[3];
    for (int row = 0; row < 3; ++row)
        r[row] = a.m[row] * p[0] + a.m[4 + row] * p[1] + a.m[8 + row] * p[2] + a.m[12 + row];
    return v3((float)r[0], (float)r[1], (float)r[2]);
}

inline vec3 mat4_direction(const Mat4 &a, double x, double y, double z)
{
    double r[3];
    for (int row = 0; row < 3; ++row)
        r[row] = a.m[row] * x + a.m[4 + row] * y + a.m[8 + row] * z;
    return v3((float)r[0], (float)r[1], (float)r[2]);
}

inline double mat4_det3(const Mat4 &a)
{
    const double *m = a.m;
    return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
           m[8] * (m[1] * m[6] - m[5] * m[2]);
}

/* The cofactor matrix of the upper 3x3 part, cof(A) = det(A) A^-T: normals
 * transform by the inverse transpose, and the cofactor form needs no division
 * (the length is renormalised anyway; the sign of det is applied by the caller).
 * Returned as a 3x3 column-major array. */
inline void mat4_cofactor3(const Mat4 &a, double cof[9])
{
    auto e = [&a](int row, int col) { return a.m[4 * col + row]; };
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) {
            const int r0 = (row + 1) % 3, r1 = (row + 2) % 3, c0 = (col + 1) % 3, c1 = (col + 2) % 3;
            cof[3 * col + row] = e(r0, c0) * e(r1, c1) - e(r0, c1) * e(r1, c0);
        }
}

/* The largest length of the images of the unit axes: how much the
 * transform stretches a short distance at most, for a transform without
 * shear (rotation times scale, as TRS nodes are). */
inline double mat4_largest_scale(const Mat4 &a)
{
    double largest = 0.0;
    for (int c = 0; c < 3; ++c)
        largest = std::max(largest, std::sqrt(a.m[4 * c] * a.m[4 * c] + a.m[4 * c + 1] * a.m[4 * c + 1] +
                                              a.m[4 * c + 2] * a.m[4 * c + 2]));
    return largest;
}

inline bool mat4_is_finite(const Mat4 &a)
{
    for (double v : a.m)
        if (!std::isfinite(v))
            return false;
    return true;
}

/* ------------------------------------------------------------- the loader */

struct Loader {
    const char *path;
    gt_error *e;
    scene *s;
    tinygltf::Model model;
    std::vector<int> parent;          /* per node, -1 for a root */
    std::map<int, std::string> image_problem; /* why an image has no pixels */
    std::vector<int> image_texture;   /* glTF image -> scene texture, -1 = not yet */
    std::vector<bool> warned_mode;    /* per mesh: non-triangle primitive reported */
    bool warned_orthographic = false;
    std::vector<Mat4> world;          /* per node: global transform, once world_known */
    std::vector<char> world_known;
    bool quantization = false;        /* KHR_mesh_quantization is in extensionsUsed */
    bool quantized_primitive = false, morphed_primitive = false; /* of the primitive being read */
    double position_step = 0.0;       /* of the primitive being read, in its local units */
    std::set<int> sparse_seen;        /* sparse accessors read */
    std::vector<uv_transform> material_uv; /* per material: KHR_texture_transform, baked into texcoords */
    gltf_report *report;
    int camera_wanted = -1;           /* glTF camera index to use as the scene camera; -1: the first met */
    const char *camera_name = nullptr; /* or the glTF camera of this name */

    int fail(const char *fmt, ...) __attribute__((format(printf, 2, 3)))
    {
        char problem[768];
        va_list ap;
        va_start(ap, fmt);
        std::vsnprintf(problem, sizeof problem, fmt, ap);
        va_end(ap);
        return gt_error_set(e, path, "%s", problem);
    }
};

/* gltf_names.cpp */
std::string printable(const std::string &name);
bool range_inside(uint64_t offset, uint64_t length, uint64_t size);
const char *mode_name(int mode);
const char *component_type_name(int type);
const char *type_name(int type);

/* gltf_accessors.cpp */
/* A checked window onto count elements of element_size bytes: element i
 * starts at base + i * stride and all of them lie inside the buffer. */
struct AccessorView {
    const unsigned char *base;
    size_t stride, count;
};

int view_elements(Loader &L, const std::string &what, const char *role, int view_index, size_t offset, size_t count,
                  size_t element_size, bool use_stride, AccessorView *v);
/* What a role accepts: core glTF 2.0 ("Meshes", attribute table), and with
 * KHR_mesh_quantization (declared in extensionsUsed) its additions. */
struct RoleTypes {
    const char *name;
    int type;
    unsigned core, quantized;
};

extern const RoleTypes role_position, role_normal, role_texcoord, role_target_position, role_target_normal,
    role_weights, role_joints, role_indices, role_bind_matrices;
/* The accessor as floats (dequantized, sparse applied), checked against the role. */
int read_floats(Loader &L, const std::string &what, const RoleTypes &role, int index, std::vector<float> &out);
/* The accessor as unsigned integers (indices, joints). */
int read_uints(Loader &L, const std::string &what, const RoleTypes &role, int index, std::vector<uint32_t> &out);
const tinygltf::Value &member(const tinygltf::Value &o, const char *key);
int64_t member_count(const tinygltf::Value &o, const char *key, int64_t absent);
std::string member_string(const tinygltf::Value &o, const char *key, const char *absent);
bool member_numbers(const tinygltf::Value &o, const char *key, int n, const double *fallback, double *out);
const tinygltf::Value *extension(const tinygltf::ExtensionMap &extensions, const char *name);
/* Decodes every EXT_meshopt_compression bufferView into a buffer of its own. */
int decode_meshopt_views(Loader &L);

/* gltf_primitive.cpp */
/* The node's own transform (matrix, or TRS), checked. */
int node_local_matrix(Loader &L, int index, Mat4 *out);
/* One triangle primitive in its mesh's local space (or, skinned, in world
 * space), as a triangle list. */
struct Primitive {
    std::vector<float> positions, normals, texcoords;
    std::vector<uint32_t> indices;
    std::vector<uint32_t> joints; /* influences per vertex, each set of JOINTS_n/WEIGHTS_n adds 4 */
    std::vector<float> weights;
    int influences = 0;
    bool skinned = false;
};

int read_primitive(Loader &L, const std::string &what, const tinygltf::Node &node, const tinygltf::Mesh &mesh,
                   const tinygltf::Primitive &prim, Primitive &out);
int world_of(Loader &L, int node, Mat4 *out);

} // namespace gltf_detail

#endif
