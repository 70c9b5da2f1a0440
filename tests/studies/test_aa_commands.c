/* `gtlab approx aa` and its --raw frames (studies/aa_commands.h) on a tiny
 * pan of builtin:aa-thin: the raw frames hold the schema's channels, frame 0
 * has no motion, later frames do, and the jitter of the edge TAA's frames
 * alternates in the header; the approx output's values are display values;
 * an unknown scene is refused with a message naming it; the technique
 * names round-trip. */
#include <string.h>

#include "core/exr_io.h"
#include "core/reference_schema.h"
#include "studies/aa_commands.h"
#include "tests/check.h"

static void check_raw_frames(const char *dir)
{
    for (int k = 0; k < 3; ++k) {
        char path[4096 + 32];
        snprintf(path, sizeof path, "%s/frame_%03d.exr", dir, k);
        image img;
        gt_error e;
        CHECK_MSG(exr_read(path, &img, &e) == 0, "%s", e.message);
        const float *mx = image_channel_data(&img, CH_MOTION_X), *d = image_channel_data(&img, CH_DEPTH);
        CHECK(mx && d && image_channel_data(&img, CH_DISOCCLUDED) && image_channel_data(&img, "frame.G"));
        double motion = 0.0;
        for (size_t p = 0; mx && p < image_pixel_count(&img); ++p)
            motion = fmax(motion, fabs(mx[p]));
        CHECK_MSG(k == 0 ? motion == 0.0 : motion > 0.05, "frame %d: largest |motion.X| %g", k, motion);
        const char *jitter = image_get_attribute(&img, ATTR_JITTER);
        CHECK(jitter && strcmp(jitter, k % 2 ? "0.5 0" : "0 0.5") == 0);
        image_free(&img);
    }
}

int main(void)
{
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", check_tmp_dir());
    aa_frames_request rq = {"builtin:aa-thin", 40, 30, 3, {0.04f, 0.0f, 0.0f}, 0.25f, 3, dir, 2};
    gt_error e;
    CHECK_MSG(aa_frames_write(&rq, &e) == 0, "%s", e.message);
    check_raw_frames(dir);
    CHECK_MSG(aa_approx(&rq, &e) == 0, "%s", e.message);
    char path[4096 + 32];
    snprintf(path, sizeof path, "%s/edge-taa_002.exr", dir);
    image img;
    CHECK_MSG(exr_read(path, &img, &e) == 0, "%s", e.message);
    const float *g = image_channel_data(&img, "frame.G");
    int in_range = g != NULL;
    for (size_t p = 0; g && p < image_pixel_count(&img); ++p)
        in_range &= g[p] >= 0.0f && g[p] <= 1.0f;
    CHECK(in_range);
    image_free(&img);
    rq.scene = "builtin:no-such-scene";
    CHECK(aa_frames_write(&rq, &e) != 0 && strstr(e.message, "no-such-scene") != NULL);
    for (int t = 0; t < AA_T_TECHNIQUES; ++t)
        CHECK(aa_technique_parse(aa_technique_short_name(t)) == t);
    CHECK(aa_technique_parse("smaa") == -1);
    return check_report("studies_aa_commands");
}
