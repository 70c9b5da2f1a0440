#include "project/study_context.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "scene/scene_loaders.h"

const char *study_quality_name(study_quality quality)
{
    return quality == QUALITY_PRODUCTION ? "production" : "preview";
}

int study_make_dir(const study_context *ctx, const char *sub, char *path, size_t size, gt_error *e)
{
    snprintf(path, size, "%s/%s", ctx->output_dir, sub);
    if (mkdir(path, 0755) != 0 && errno != EEXIST)
        return gt_error_set(e, path, "cannot create folder: %s", strerror(errno));
    return 0;
}

int study_load_view(const char *spec, int width, int height, scene *s, camera *cam, gt_error *e)
{
    if (scene_load(spec, s, e) != 0)
        return -1;
    if (scene_choose_camera(s, NULL, width, height, cam, e) != 0) {
        scene_free(s);
        return -1;
    }
    return 0;
}
