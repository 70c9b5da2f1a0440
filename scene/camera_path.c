/* Camera paths (camera_path.h). */
#include "scene/camera_path.h"

#include <math.h>

camera_path camera_path_static(const camera *cam)
{
    camera_path p = {*cam, v3(0.0f, 0.0f, 0.0f), 0.0f};
    return p;
}

/* v turned by angle about +Y (right-handed: counter-clockwise seen from above). */
static vec3 yaw(vec3 v, double angle)
{
    double c = cos(angle), s = sin(angle);
    return v3((float)(c * v.x + s * v.z), v.y, (float)(-s * v.x + c * v.z));
}

camera camera_path_at(const camera_path *path, int k)
{
    camera cam = path->start;
    vec3 look = v3_sub(path->start.target, path->start.position);
    cam.position = v3_add(path->start.position, v3_scale(path->step, (float)k));
    cam.target = v3_add(cam.position, yaw(look, (double)path->yaw_step * k));
    return cam;
}

/* camera_ray: d ~ forward + sx right + sy up with sx = (2x/W - 1) t a,
 * sy = (1 - 2y/H) t (t = tan(yfov/2), a = W/H); solved for x, y. */
float camera_project_direction(const camera_view *view, vec3 d, float xy[2])
{
    float depth = v3_dot(d, view->forward);
    if (depth <= 0.0f)
        return depth;
    float sx = v3_dot(d, view->right) / depth, sy = v3_dot(d, view->up) / depth;
    xy[0] = 0.5f * (float)view->width * (1.0f + sx / (view->tan_half_yfov * view->aspect));
    xy[1] = 0.5f * (float)view->height * (1.0f - sy / view->tan_half_yfov);
    return depth;
}

float camera_project(const camera_view *view, vec3 p, float xy[2])
{
    return camera_project_direction(view, v3_sub(p, view->origin), xy);
}
