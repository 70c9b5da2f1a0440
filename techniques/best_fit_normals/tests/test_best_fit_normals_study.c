/* The best-fit normals study's numbers, on a small request:
 * - the normalised RGB8 encoding's worst error is below the bound of a cell
 *   (half-diagonal sqrt(3)/255 at unit radius: asin(sqrt(3)/255));
 * - the best fit beats the normalised and the max-component encodings, and
 *   the precise octahedral encode never loses to the plain one;
 * - the exhaustive best cell's highlight is at least as close as the
 *   normalised encoding's, and every DSSIM is small and non-negative;
 * - the exact cell counts are the closed forms (surface 256^3 - 254^3), and
 *   each sampled count grows with the face size. */
#include <math.h>
#include <stdio.h>

#include "core/vec3.h" /* M_PI */
#include "best_fit_normals/best_fit_normals_study.h"
#include "tests/check.h"

int main(void)
{
    study_context ctx = {.output_dir = check_tmp_dir(), .quality = QUALITY_PREVIEW, .threads = 2};
    normals_request rq = normals_default_request(QUALITY_PREVIEW);
    rq.directions = 20000, rq.exhaustive_directions = 1000, rq.face_count = 2;
    rq.faces[0] = 64, rq.faces[1] = 128;
    static normals_result r;
    gt_error e;
    int rc = normals_study(&ctx, &rq, &r, &e);
    CHECK_MSG(rc == 0, "%s", rc ? e.message : "");
    const normals_encoding_result *naive = &r.encodings[0], *max = &r.encodings[1], *fit = &r.encodings[2];
    CHECK_MSG(naive->max_deg < asin(sqrt(3.0) / 255.0) * 180.0 / M_PI, "%g", naive->max_deg);
    CHECK(fit->mean_deg < naive->mean_deg && fit->mean_deg < max->mean_deg && fit->p99_deg < naive->p99_deg);
    for (int k = 5; k < 11; k += 2)
        CHECK_MSG(r.encodings[k + 1].mean_deg <= r.encodings[k].mean_deg &&
                      r.encodings[k + 1].max_deg <= r.encodings[k].max_deg, "%s", r.encodings[k].name);
    for (int i = 0; i < 4; ++i) {
        CHECK(r.encodings[4].highlight_dssim[i] <= naive->highlight_dssim[i]);
        for (int k = 0; k < 11; ++k)
            CHECK(r.encodings[k].highlight_dssim[i] >= 0.0 && r.encodings[k].highlight_dssim[i] < 0.1);
    }
    CHECK(r.cells_surface == 256L * 256 * 256 - 254L * 254 * 254);
    CHECK(r.sampled[0].naive < r.sampled[1].naive && r.sampled[0].best_fit < r.sampled[1].best_fit &&
          r.sampled[1].naive < r.cells_sphere);
    printf("naive %.4f/%.4f/%.4f  fit %.4f/%.4f/%.4f  exhaustive %.4f deg; dssim r=0.1 naive %.2e fit %.2e\n",
           naive->mean_deg, naive->p99_deg, naive->max_deg, fit->mean_deg, fit->p99_deg, fit->max_deg,
           r.encodings[4].mean_deg, naive->highlight_dssim[0], fit->highlight_dssim[0]);
    return check_report("test_best_fit_normals_study");
}
