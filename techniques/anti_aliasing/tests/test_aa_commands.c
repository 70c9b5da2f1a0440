/* `gtlab render frames` and `gtlab approx anti-aliasing` (anti_aliasing/aa_commands.h) on a
 * tiny pan of builtin:aa-thin: the frames hold the schema's channels, frame
 * 0 has no motion, later frames do, and the jitter of the edge TAA's frames
 * alternates in the header; with a truth, its channels and header are
 * there, where every sample under the filter sees the sky the truth is the
 * sky's radiance (the filter's weights sum to 1), and the files are the same
 * bits for 1 and 2 threads; the approx output's values are display values;
 * an unknown scene is refused with a message naming it; the technique
 * names round-trip. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "anti_aliasing/aa_commands.h"
#include "core/files/exr_io.h"
#include "core/sampling/pixel_filter.h"
#include "core/reference_schema.h"
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

/* 1 where depth is 0 (sky) in the whole (2 r + 1)^2 neighbourhood. */
static int sky_around(const float *depth, int width, int height, int x, int y, int r)
{
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            int u = x + dx, v = y + dy;
            if (u < 0 || v < 0 || u >= width || v >= height || depth[(size_t)v * width + u] != 0.0f)
                return 0;
        }
    return 1;
}

static void check_truth(const char *dir)
{
    char path[4096 + 32];
    snprintf(path, sizeof path, "%s/frame_001.exr", dir);
    image img;
    gt_error e;
    CHECK_MSG(exr_read(path, &img, &e) == 0, "%s", e.message);
    const char *how = image_get_attribute(&img, ATTR_TRUTH);
    const float *truth = image_channel_data(&img, "truth.B"), *frame = image_channel_data(&img, "frame.B"),
                *depth = image_channel_data(&img, CH_DEPTH);
    CHECK(how && strstr(how, "4 x 4 strata, blackman-harris") != NULL && truth && frame && depth);
    int sky = 0;
    for (int y = 0; truth && frame && depth && y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            if (sky_around(depth, img.width, img.height, x, y, 4)) {
                size_t p = (size_t)y * img.width + x;
                CHECK_MSG(fabsf(truth[p] - frame[p]) <= 1e-6f * frame[p], "sky pixel (%d, %d): truth %.9g, frame "
                          "%.9g", x, y, truth[p], frame[p]);
                ++sky;
            }
    CHECK_MSG(sky >= 10, "%d sky pixels", sky);
    image_free(&img);
}

/* Whether two files hold the same bytes. */
static int files_equal(const char *a, const char *b)
{
    FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
    int equal = fa && fb, ca = 0, cb = 0;
    while (equal && ca != EOF)
        equal = (ca = fgetc(fa)) == (cb = fgetc(fb));
    if (fa)
        fclose(fa);
    if (fb)
        fclose(fb);
    return equal;
}

/* Frames with a truth, on 1 and 2 threads: the same bits. */
static void check_threads(aa_frames_request rq, const char *dir)
{
    char one[4096 + 16], two[4096 + 16];
    snprintf(one, sizeof one, "%s/threads1", dir);
    snprintf(two, sizeof two, "%s/threads2", dir);
    mkdir(one, 0755), mkdir(two, 0755);
    gt_error e;
    rq.truth_strata = 4, rq.truth_filter = PIXEL_FILTER_BLACKMAN_HARRIS, rq.frames = 2;
    rq.dir = one, rq.threads = 1;
    CHECK_MSG(aa_frames_write(&rq, &e) == 0, "%s", e.message);
    rq.dir = two, rq.threads = 2;
    CHECK_MSG(aa_frames_write(&rq, &e) == 0, "%s", e.message);
    check_truth(one);
    char a[4096 + 32], b[4096 + 32];
    snprintf(a, sizeof a, "%s/frame_001.exr", one);
    snprintf(b, sizeof b, "%s/frame_001.exr", two);
    CHECK(files_equal(a, b));
}

int main(void)
{
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", check_tmp_dir());
    aa_frames_request rq = {"builtin:aa-thin", 40, 30, 3, {0.04f, 0.0f, 0.0f}, 0.25f, 3, dir, 2, 0, 0};
    gt_error e;
    CHECK_MSG(aa_frames_write(&rq, &e) == 0, "%s", e.message);
    check_raw_frames(dir);
    check_threads(rq, dir);
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
    return check_report("test_aa_commands");
}
