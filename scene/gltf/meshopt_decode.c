/* EXT_meshopt_compression through libmeshoptimizer's C API: see meshopt_decode.h. */
#include "scene/gltf/meshopt_decode.h"

#include <meshoptimizer.h>
#include <string.h>

static int is(const char *text, const char *name)
{
    return strcmp(text, name) == 0;
}

static int check_stride(const meshopt_view *v, const char *what, gt_error *e)
{
    const size_t s = v->stride;
    if (is(v->mode, "ATTRIBUTES") && (s == 0 || s % 4 != 0 || s > 256))
        return gt_error_set(e, what, "EXT_meshopt_compression: ATTRIBUTES byteStride %zu is not a multiple of 4 "
                                     "from 4 to 256", s);
    if (!is(v->mode, "ATTRIBUTES") && s != 2 && s != 4)
        return gt_error_set(e, what, "EXT_meshopt_compression: %s byteStride %zu is not 2 or 4", v->mode, s);
    if (is(v->mode, "TRIANGLES") && v->count % 3 != 0)
        return gt_error_set(e, what, "EXT_meshopt_compression: TRIANGLES count %zu is not a multiple of 3", v->count);
    return 0;
}

static int check_filter(const meshopt_view *v, const char *what, gt_error *e)
{
    const size_t s = v->stride;
    if (is(v->filter, "NONE"))
        return 0;
    if (!is(v->mode, "ATTRIBUTES"))
        return gt_error_set(e, what, "EXT_meshopt_compression: filter %s on %s data", v->filter, v->mode);
    if ((is(v->filter, "OCTAHEDRAL") && s != 4 && s != 8) || (is(v->filter, "QUATERNION") && s != 8))
        return gt_error_set(e, what, "EXT_meshopt_compression: filter %s with byteStride %zu", v->filter, s);
    if (is(v->filter, "OCTAHEDRAL") || is(v->filter, "QUATERNION") || is(v->filter, "EXPONENTIAL"))
        return 0;
    gt_quoted q;
    return gt_error_set(e, what, "EXT_meshopt_compression: unknown filter \"%s\"", gt_quote(v->filter, &q));
}

int meshopt_check_view(const meshopt_view *v, const char *what, gt_error *e)
{
    if (!is(v->mode, "ATTRIBUTES") && !is(v->mode, "TRIANGLES") && !is(v->mode, "INDICES")) {
        gt_quoted q;
        return gt_error_set(e, what, "EXT_meshopt_compression: unknown mode \"%s\"", gt_quote(v->mode, &q));
    }
    return check_stride(v, what, e) != 0 ? -1 : check_filter(v, what, e);
}

static void apply_filter(const meshopt_view *v, unsigned char *dst)
{
    if (is(v->filter, "OCTAHEDRAL"))
        meshopt_decodeFilterOct(dst, v->count, v->stride);
    else if (is(v->filter, "QUATERNION"))
        meshopt_decodeFilterQuat(dst, v->count, v->stride);
    else if (is(v->filter, "EXPONENTIAL"))
        meshopt_decodeFilterExp(dst, v->count, v->stride);
}

int meshopt_decode_view(const meshopt_view *v, const unsigned char *src, size_t src_size, unsigned char *dst,
                        const char *what, gt_error *e)
{
    if (meshopt_check_view(v, what, e) != 0)
        return -1;
    int rc;
    if (is(v->mode, "ATTRIBUTES"))
        rc = meshopt_decodeVertexBuffer(dst, v->count, v->stride, src, src_size);
    else if (is(v->mode, "TRIANGLES"))
        rc = meshopt_decodeIndexBuffer(dst, v->count, v->stride, src, src_size);
    else
        rc = meshopt_decodeIndexSequence(dst, v->count, v->stride, src, src_size);
    if (rc != 0)
        return gt_error_set(e, what, "EXT_meshopt_compression: %s data does not decode (meshoptimizer error %d)",
                            v->mode, rc);
    apply_filter(v, dst);
    return 0;
}
