/* The DFG study (dfg/dfg_study.h): the DFG section's numbers without its
 * prose, on small tables. The written table's files exist and its albedo E
 * is a fraction; the lookup is scored per size, worse over the whole square
 * (clamped borders) than between the texel centres, and better at 32 than
 * at 16; Filament's 128 is flagged only when studied; bad requests are
 * refused. */
#include "dfg/dfg_study.h"
#include "tests/check.h"
#include "tests/test_files.h"

static void test_small_study(void)
{
    char dir[2048], path[4096];
    gt_error e;
    study_context top = {check_tmp_dir(), QUALITY_PREVIEW, 2, NULL, NULL, 0};
    CHECK(study_make_dir(&top, "dfg_study", dir, sizeof dir, &e) == 0);
    study_context ctx = {dir, QUALITY_PREVIEW, 2, NULL, NULL, 0};
    dfg_request rq = {32, {16, 32}, 2, 256, 1};
    static dfg_result r;
    CHECK_MSG(dfg_study(&ctx, &rq, &r, &e) == 0, "%s", e.message);
    CHECK(r.e_min > 0.0 && r.e_min <= 1.0);
    CHECK(r.max_error_estimate > 0.0 && r.max_error_estimate < 1e-5);
    CHECK(r.filament_row == -1);
    for (int k = 0; k < 2; ++k) {
        CHECK(r.by_size[k].size == rq.sizes[k]);
        CHECK(r.by_size[k].interior_points > 0 && r.by_size[k].interior_points <= rq.points);
        CHECK(r.by_size[k].max_error[DFG_ALBEDO] >= r.by_size[k].interior_max_error[DFG_ALBEDO]);
    }
    CHECK(r.by_size[1].interior_rms_error[DFG_ALBEDO] < r.by_size[0].interior_rms_error[DFG_ALBEDO]);
    const char *files[] = {"dfg_32.exr", "dfg_32.png", "dfg_32.h", "dfg_32.hlsl", "dfg_interpolation.dat"};
    for (int i = 0; i < 5; ++i) {
        snprintf(path, sizeof path, "%s/%s/%s", dir, DFG_LUTS_DIR, files[i]);
        CHECK_MSG(file_exists(path), "%s not written", path);
    }
}

static void test_bad_requests(void)
{
    gt_error e;
    study_context ctx = {check_tmp_dir(), QUALITY_PREVIEW, 1, NULL, NULL, 0};
    static dfg_result r;
    dfg_request none = {32, {0}, 0, 16, 1}, too_small = {8, {16}, 1, 16, 1};
    CHECK(dfg_study(&ctx, &none, &r, &e) != 0);
    CHECK(dfg_study(&ctx, &too_small, &r, &e) != 0);
}

static void test_default_requests(void)
{
    dfg_request preview = dfg_default_request(QUALITY_PREVIEW), production = dfg_default_request(QUALITY_PRODUCTION);
    CHECK(preview.size == DFG_FILAMENT_SIZE && production.size == DFG_FILAMENT_SIZE);
    CHECK(production.size_count > preview.size_count && production.points > preview.points);
}

int main(void)
{
    test_small_study();
    test_bad_requests();
    test_default_requests();
    return check_report("dfg_study");
}
