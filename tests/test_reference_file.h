/* A small reference of a scene view rendered into an EXR file, for the tests
 * that score files (e.g. tests/gpu/test_gpu_*function_score.c). */
#ifndef GTLAB_TESTS_TEST_REFERENCE_FILE_H
#define GTLAB_TESTS_TEST_REFERENCE_FILE_H

#include "core/files/exr_io.h"
#include "raytracer/reference_render.h"
#include "project/study_context.h"
#include "tests/check.h"

/* Renders rq of `spec` seen by its study view at width x height into path; 0, or -1 after a failed CHECK. */
static inline int test_render_reference_file(const char *spec, int width, int height, const reference_request *rq,
                                             const char *path)
{
    scene s;
    camera cam;
    image img;
    render_stats stats;
    gt_error e = {{0}};
    int rc = study_load_view(spec, width, height, &s, &cam, &e);
    if (rc == 0) {
        rc = reference_render(&s, spec, &cam, rq, &img, &stats, &e);
        scene_free(&s);
    }
    if (rc == 0) {
        rc = exr_write(path, &img, &e);
        image_free(&img);
    }
    CHECK_MSG(rc == 0, "%s", e.message);
    return rc;
}

#endif
