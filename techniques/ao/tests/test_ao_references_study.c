/* ao_references: the AO stage's numbers without its prose. On the
 * open plane every ray escapes, so AO is exactly 1 with zero standard error
 * and a zero noise floor; in the corner it is not, and the row's statistics
 * are consistent (mean <= max, every pixel took every sample); the rows do
 * not depend on the thread count; the references and previews are written;
 * the quality table's scene set is large enough to decide (issue 46). */
#include "ao/ao_references.h"
#include "tests/check.h"
#include "tests/test_files.h"

#include <string.h>

#include "ao/ao_quality.h"
#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "project/scene_list.h"

static int run(int threads, const char *sub, ao_references_result *r)
{
    char dir[4096];
    gt_error e;
    study_context top = {check_tmp_dir(), QUALITY_PREVIEW, threads, NULL, NULL, 0};
    CHECK(study_make_dir(&top, sub, dir, sizeof dir, &e) == 0);
    study_context ctx = {dir, QUALITY_PREVIEW, threads, NULL, NULL, 0};
    ao_references_request rq = {32, 16, 0.0, 1, 3}; /* plane, sphere-on-plane, corner */
    int rc = ao_references_study(&ctx, &rq, r, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    return rc;
}

static void test_open_plane_is_exact(const ao_references_result *r)
{
    const ao_reference_row *plane = &r->rows[0];
    CHECK(strcmp(plane->scene, "plane") == 0);
    CHECK(plane->covered_pixels > 0);
    CHECK(plane->mean_stderr == 0.0 && plane->max_stderr == 0.0);
    CHECK(plane->noise_floor_dssim == 0.0);
    CHECK(plane->mean_spp == 16.0);
}

static void test_corner_statistics(const ao_references_result *r)
{
    const ao_reference_row *corner = &r->rows[2];
    CHECK(strcmp(corner->scene, "corner") == 0);
    CHECK(corner->max_stderr > 0.0);
    CHECK(corner->mean_stderr > 0.0 && corner->mean_stderr <= corner->max_stderr);
    CHECK(corner->noise_floor_dssim > 0.0);
    CHECK(corner->mean_spp == 16.0);
    CHECK(corner->covered_pixels <= corner->width * corner->height);
}

static void test_thread_independent(const ao_references_result *a, const ao_references_result *b)
{
    CHECK(a->count == 3 && b->count == 3);
    for (int i = 0; i < a->count; ++i) {
        CHECK(a->rows[i].mean_stderr == b->rows[i].mean_stderr);
        CHECK(a->rows[i].max_stderr == b->rows[i].max_stderr);
        CHECK(a->rows[i].noise_floor_dssim == b->rows[i].noise_floor_dssim);
        CHECK(a->rows[i].covered_pixels == b->rows[i].covered_pixels);
    }
}

static void test_files_written(void)
{
    char path[4096];
    image img;
    gt_error e;
    snprintf(path, sizeof path, "%s/one/ao/corner.exr", check_tmp_dir());
    CHECK_MSG(exr_read(path, &img, &e) == 0, "%s", e.message);
    CHECK(image_channel_data(&img, CH_AO) && image_channel_data(&img, CH_AO_STDERR));
    image_free(&img);
    snprintf(path, sizeof path, "%s/one/ao/corner.camera.json", check_tmp_dir());
    CHECK(file_exists(path));
    snprintf(path, sizeof path, "%s/one/figures/ao_stderr_corner.png", check_tmp_dir());
    CHECK(file_exists(path));
}

/* Issue 46: rankings paired over at least 8 scenes at preview and 24 at
 * production, and every study can hold them. */
static void test_scene_set_size(void)
{
    const int preview = ao_quality_of(QUALITY_PREVIEW)->study_scenes;
    const int production = ao_quality_of(QUALITY_PRODUCTION)->study_scenes;
    CHECK(preview >= 8 && production >= 24 && production <= STUDY_SCENES_MAX && AO_REFERENCES_MAX_SCENES >= production);
    study_context ctx = {check_tmp_dir(), QUALITY_PRODUCTION, 1, NULL, NULL, production};
    CHECK(study_scene_count(&ctx) == production);
}

int main(void)
{
    test_scene_set_size();
    static ao_references_result one, two;
    if (run(1, "one", &one) == 0 && run(2, "two", &two) == 0) {
        test_open_plane_is_exact(&one);
        test_corner_statistics(&one);
        test_thread_independent(&one, &two);
        test_files_written();
    }
    return check_report("studies_ao_references");
}
