/* Pinhole cameras (DESIGN.md "Camera JSON"). */
#include "scene/camera.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/atomic_file.h"
#include "core/files/input_file.h"
#include "core/files/json_check.h"
#include "core/files/json_unique_keys.h"
#include "core/sampling/hemisphere_sampling.h"

static const float degrees_per_radian = (float)(180.0 / M_PI);

int camera_validate(const camera *cam, const char *what, gt_error *e)
{
    if (!v3_is_finite(cam->position) || !v3_is_finite(cam->target) || !v3_is_finite(cam->up))
        return gt_error_set(e, what, "camera has non-finite position, target or up");
    vec3 forward = v3_sub(cam->target, cam->position);
    if (v3_length(forward) <= 0.0f)
        return gt_error_set(e, what, "camera position and target coincide");
    if (v3_length(v3_cross(v3_normalize(forward), cam->up)) < 1e-6f)
        return gt_error_set(e, what, "camera up is parallel to the view direction (or zero)");
    if (!(cam->yfov > 0.0f && cam->yfov < (float)M_PI))
        return gt_error_set(e, what, "yfov_deg must be in (0, 180), got %g", cam->yfov * degrees_per_radian);
    if (cam->width <= 0 || cam->height <= 0 || cam->width > 65536 || cam->height > 65536)
        return gt_error_set(e, what, "image size %dx%d is out of range [1, 65536]", cam->width, cam->height);
    return 0;
}

camera_view camera_view_from(const camera *cam)
{
    camera_view v;
    v.origin = cam->position;
    v.forward = v3_normalize(v3_sub(cam->target, cam->position));
    v.right = v3_normalize(v3_cross(v.forward, cam->up));
    v.up = v3_cross(v.right, v.forward);
    v.tan_half_yfov = tanf(0.5f * cam->yfov);
    v.aspect = (float)cam->width / (float)cam->height;
    v.width = cam->width;
    v.height = cam->height;
    return v;
}

void camera_ray(const camera_view *view, float x, float y, vec3 *origin, vec3 *direction)
{
    float sx = (2.0f * x / (float)view->width - 1.0f) * view->tan_half_yfov * view->aspect;
    float sy = (1.0f - 2.0f * y / (float)view->height) * view->tan_half_yfov;
    *origin = view->origin;
    *direction = v3_normalize(v3_add(view->forward, v3_add(v3_scale(view->right, sx), v3_scale(view->up, sy))));
}

float camera_depth(const camera_view *view, vec3 p) { return v3_dot(v3_sub(p, view->origin), view->forward); }

static int read_vec3(const cJSON *root, const char *key, int required, vec3 *out, const char *what, gt_error *e)
{
    const cJSON *arr = cJSON_GetObjectItemCaseSensitive(root, key);
    if (!arr)
        return required ? gt_error_set(e, what, "camera JSON lacks \"%s\"", key) : 0;
    float v[3];
    if (!cJSON_IsArray(arr) || cJSON_GetArraySize(arr) != 3)
        return gt_error_set(e, what, "\"%s\" must be an array of 3 numbers", key);
    for (int i = 0; i < 3; ++i) {
        const cJSON *item = cJSON_GetArrayItem(arr, i);
        if (!cJSON_IsNumber(item))
            return gt_error_set(e, what, "\"%s\" must be an array of 3 numbers", key);
        v[i] = (float)item->valuedouble;
    }
    *out = v3(v[0], v[1], v[2]);
    return 0;
}

static int read_number(const cJSON *root, const char *key, double *out, const char *what, gt_error *e)
{
    const cJSON *item = cJSON_GetObjectItemCaseSensitive(root, key);
    if (!item)
        return gt_error_set(e, what, "camera JSON lacks \"%s\"", key);
    if (!cJSON_IsNumber(item))
        return gt_error_set(e, what, "\"%s\" must be a number", key);
    *out = item->valuedouble;
    return 0;
}

static int read_size(const cJSON *root, const char *key, int *out, const char *what, gt_error *e)
{
    double v = 0.0;
    if (read_number(root, key, &v, what, e) != 0)
        return -1;
    /* Range first: converting an out-of-range double to int is undefined. */
    if (!(v >= 1 && v <= 65536) || v != floor(v))
        return gt_error_set(e, what, "\"%s\" must be a whole number in [1, 65536]", key);
    *out = (int)v;
    return 0;
}

/* The camera of a cJSON object. */
static int camera_from_json(const cJSON *root, const char *what, camera *cam, gt_error *e)
{
    camera c;
    c.up = v3(0.0f, 1.0f, 0.0f);
    double yfov_deg = 0.0;
    int rc = read_vec3(root, "position", 1, &c.position, what, e);
    if (rc == 0)
        rc = read_vec3(root, "target", 1, &c.target, what, e);
    if (rc == 0)
        rc = read_vec3(root, "up", 0, &c.up, what, e);
    if (rc == 0)
        rc = read_number(root, "yfov_deg", &yfov_deg, what, e);
    if (rc == 0)
        rc = read_size(root, "width", &c.width, what, e);
    if (rc == 0)
        rc = read_size(root, "height", &c.height, what, e);
    if (rc != 0)
        return rc;
    c.yfov = (float)yfov_deg / degrees_per_radian;
    if (camera_validate(&c, what, e) != 0)
        return -1;
    *cam = c;
    return 0;
}

/* text[0, length) has passed the JSON gate and text[length] is a NUL. */
static int camera_parse_checked(const char *text, size_t length, const char *what, camera *cam, gt_error *e)
{
    const size_t bom = json_bom_length(text, length);
    /* With the NUL in the length, as cJSON wants for require_null_terminated. */
    cJSON *root = cJSON_ParseWithLengthOpts(text + bom, length - bom + 1, NULL, 1);
    int rc = !root || !cJSON_IsObject(root) ? gt_error_set(e, what, "not a JSON object (camera JSON expected)")
             : json_check_unique_keys(root, what, e) != 0 ? -1
                                                           : camera_from_json(root, what, cam, e);
    cJSON_Delete(root);
    return rc;
}

int camera_parse_json_bytes(const char *text, size_t length, const char *what, camera *cam, gt_error *e)
{
    if (json_check(text, length, json_limits_cjson, what, e) != 0)
        return -1;
    char *copy = malloc(length + 1);
    if (!copy)
        return gt_error_set(e, what, "out of memory");
    memcpy(copy, text, length);
    copy[length] = '\0';
    int rc = camera_parse_checked(copy, length, what, cam, e);
    free(copy);
    return rc;
}

int camera_parse_json(const char *text, const char *what, camera *cam, gt_error *e)
{
    const size_t length = strlen(text);
    if (json_check(text, length, json_limits_cjson, what, e) != 0)
        return -1;
    return camera_parse_checked(text, length, what, cam, e);
}

int camera_read_json(const char *path, camera *cam, gt_error *e)
{
    enum { max_size = 65536 - 1 };
    char *text;
    size_t n;
    if (input_file_read(path, max_size, "camera JSON larger than 64 KiB", &text, &n, e) != 0)
        return -1;
    /* All n bytes: a NUL inside the file is an error, not the end. */
    int rc = camera_parse_json_bytes(text, n, path, cam, e);
    free(text);
    return rc;
}

static cJSON *vec3_json(vec3 v)
{
    const double d[3] = {v.x, v.y, v.z};
    return cJSON_CreateDoubleArray(d, 3);
}

char *camera_to_json(const camera *cam)
{
    cJSON *root = cJSON_CreateObject();
    cJSON_AddItemToObject(root, "position", vec3_json(cam->position));
    cJSON_AddItemToObject(root, "target", vec3_json(cam->target));
    cJSON_AddItemToObject(root, "up", vec3_json(cam->up));
    cJSON_AddNumberToObject(root, "yfov_deg", cam->yfov * degrees_per_radian);
    cJSON_AddNumberToObject(root, "width", cam->width);
    cJSON_AddNumberToObject(root, "height", cam->height);
    char *text = cJSON_PrintUnformatted(root);
    cJSON_Delete(root);
    return text;
}

int camera_write_json(const char *path, const camera *cam, gt_error *e)
{
    char *text = camera_to_json(cam);
    if (!text)
        return gt_error_set(e, path, "out of memory");
    size_t n = strlen(text);
    char *with_newline = malloc(n + 2);
    if (!with_newline) {
        free(text);
        return gt_error_set(e, path, "out of memory");
    }
    memcpy(with_newline, text, n);
    strcpy(with_newline + n, "\n");
    int rc = atomic_write_text(path, with_newline, e);
    free(with_newline);
    free(text);
    return rc;
}

camera camera_auto_framing(vec3 lo, vec3 hi, int width, int height)
{
    camera c;
    vec3 centre = v3_scale(v3_add(lo, hi), 0.5f);
    float radius = 0.5f * v3_length(v3_sub(hi, lo));
    if (!(radius > 0.0f))
        radius = 1.0f;
    c.yfov = 45.0f / degrees_per_radian;
    c.width = width;
    c.height = height;
    /* Fit the bounding sphere inside the narrower of the two fields of view. */
    float half_fov = 0.5f * c.yfov;
    if (width < height)
        half_fov = atanf(tanf(half_fov) * (float)width / (float)height);
    float distance = 1.05f * radius / sinf(half_fov);
    vec3 view_direction = v3_normalize(v3(0.6f, 0.5f, 0.8f)); /* from the target, a 3/4 view from above */
    c.target = centre;
    c.position = v3_add(centre, v3_scale(view_direction, distance));
    c.up = v3(0.0f, 1.0f, 0.0f);
    return c;
}

void camera_sidecar_path(const char *output_path, char *out, int out_size)
{
    size_t n = strlen(output_path);
    int stem = (int)n;
    if (n >= 4 && strcmp(output_path + n - 4, ".exr") == 0)
        stem = (int)n - 4;
    snprintf(out, (size_t)out_size, "%.*s.camera.json", stem, output_path);
}
