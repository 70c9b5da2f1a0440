/* volumetric_light/volumetric_light_raymarch.h and volumetric_light/volumetric_light_upsample.h against the
 * reference and against statistics, on a spot light above a floor (y = 0),
 * the camera rays ending on the floor:
 *  - with many uniform steps the ray-march converges to the reference
 *    quadrature (techniques/volumetric_light/volumetric_light_integral.h, an independent
 *    integrator in another variable), its error falling as 1/N (the steps
 *    are a left Riemann sum and the integrand does not vanish at the floor);
 *  - every noise type is unbiased: the mean over frames of a 3-step march
 *    with a shadow map equals the 20000-step result within 4 standard
 *    errors (per pixel and over the image), while no noise stays biased;
 *  - blue-noise offsets keep a flat histogram in every frame and carry less
 *    low-frequency energy than white noise (4 x 4 block means);
 *  - the half-resolution upsamples (bilinear and noisy) do not bleed across
 *    a depth edge;
 *  - the images have the same bits for 1 and 2 threads. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "volumetric_light/volumetric_light_integral.h"
#include "volumetric_light/volumetric_light_upsample.h"
#include "tests/check.h"

enum { W = 16, H = 16, FRAMES = 64 };

typedef struct {
    float dir[3 * W * H], distance[W * H];
    raymarch_view view;
} rays;

static void make_rays(rays *r)
{
    vec3 eye = v3(-5.0f, 3.0f, 4.0f);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            vec3 target = v3(-1.2f + 2.4f * (x + 0.5f) / W, 0.0f, -1.2f + 2.4f * (y + 0.5f) / H);
            vec3 w = v3_normalize(v3_sub(target, eye));
            v3_store(&r->dir[3 * (y * W + x)], w);
            r->distance[y * W + x] = -eye.y / w.y;
        }
    r->view = (raymarch_view){W, H, eye, r->dir, r->distance};
}

/* An occluder at radial distance 2.5 from the light over the texels i < 28. */
static int make_shadows(const volumetric_light *spot, shadow_map *m)
{
    gt_error e;
    if (shadow_map_alloc(m, 64, spot->position, spot->axis, acos(spot->cos_outer) * 180.0 / M_PI, 0.01, &e) != 0)
        return -1;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 28; ++i)
            m->distance[j * 64 + i] = 2.5f;
    return 0;
}

static void check_convergence(const raymarch_lighting *l, const rays *r)
{
    volumetric_lighting ref = {l->light, l->medium, NULL};
    int checked = 0;
    for (int p = 0; p < W * H; p += 37) {
        vec3 w = v3_load(&r->dir[3 * p]);
        volumetric_ray_estimate q;
        volumetric_light_quadrature(&ref, r->view.eye, w, r->distance[p], 1e-9, &q);
        double exact = q.radiance[0] / l->light->intensity[0];
        if (!(exact > 0.0))
            continue;
        ++checked;
        double e256 = fabs(raymarch_ray(l, r->view.eye, w, r->distance[p], 256, 0.0) - exact);
        double e512 = fabs(raymarch_ray(l, r->view.eye, w, r->distance[p], 512, 0.0) - exact);
        double e8192 = fabs(raymarch_ray(l, r->view.eye, w, r->distance[p], 8192, 0.0) - exact);
        CHECK_MSG(e256 / e512 > 1.8 && e256 / e512 < 2.2, "pixel %d: error 256 -> 512 steps falls by %.3g", p,
                  e256 / e512);
        CHECK_MSG(e8192 < 2e-4 * exact + q.error[0], "pixel %d: 8192 steps %.3g from %.9g", p, e8192, exact);
    }
    CHECK_MSG(checked >= 4, "%d lit pixels checked", checked);
}

static void check_unbiased(const raymarch_lighting *l, const rays *r, const blue_noise_texture *blue)
{
    float *frame = malloc(sizeof(float) * W * H), *exact = malloc(sizeof(float) * W * H);
    double *sum = calloc(W * H, sizeof(double)), *sum2 = calloc(W * H, sizeof(double));
    raymarch_image(l, &r->view, 20000, RAYMARCH_NOISE_NONE, NULL, 0, 2, exact); /* xi = 0: error ~ 1e-4 */
    for (int n = 0; n < RAYMARCH_NOISE_COUNT; ++n) {
        memset(sum, 0, sizeof(double) * W * H), memset(sum2, 0, sizeof(double) * W * H);
        for (int f = 0; f < FRAMES; ++f) {
            raymarch_image(l, &r->view, 3, (raymarch_noise)n, blue, f, 2, frame);
            for (int p = 0; p < W * H; ++p)
                sum[p] += frame[p], sum2[p] += (double)frame[p] * frame[p];
        }
        int outside = 0, biased = 0;
        double total = 0.0, total_var = 0.0, scale = 0.0;
        for (int p = 0; p < W * H; ++p) {
            double mean = sum[p] / FRAMES, var = fmax(0.0, sum2[p] / FRAMES - mean * mean) / (FRAMES - 1);
            outside += fabs(mean - exact[p]) > 4.0 * sqrt(var) + 2e-4 * exact[p] + 1e-9;
            biased += fabs(mean - exact[p]) > 0.05 * exact[p] + 1e-6;
            total += mean - exact[p], total_var += var, scale += exact[p];
        }
        if (n == RAYMARCH_NOISE_NONE) {
            CHECK_MSG(biased > W * H / 10, "no noise: only %d pixels biased", biased);
            continue;
        }
        CHECK_MSG(outside == 0, "%s: %d pixels' means outside 4 standard errors", raymarch_noise_name(n), outside);
        CHECK_MSG(fabs(total) <= 4.0 * sqrt(total_var) + 1e-4 * scale, "%s: image bias %.3g (+- %.3g)",
                  raymarch_noise_name(n), total, sqrt(total_var));
    }
    free(frame), free(exact), free(sum), free(sum2);
}

/* The variance of 4 x 4 block means of one frame's offsets over a 64 x 64 tile. */
static double block_mean_variance(raymarch_noise n, const blue_noise_texture *blue, int frame)
{
    double s = 0.0, s2 = 0.0;
    for (int by = 0; by < 16; ++by)
        for (int bx = 0; bx < 16; ++bx) {
            double m = 0.0;
            for (int k = 0; k < 16; ++k)
                m += raymarch_offset(n, blue, frame, 4 * bx + k % 4, 4 * by + k / 4) / 16.0;
            s += m, s2 += m * m;
        }
    return s2 / 256.0 - (s / 256.0) * (s / 256.0);
}

static void check_blue_noise(const blue_noise_texture *blue)
{
    for (int f = 0; f < 5; ++f) {
        int bins[16] = {0}, flat = 1;
        for (int p = 0; p < 64 * 64; ++p)
            ++bins[(int)(16.0 * raymarch_offset(RAYMARCH_NOISE_BLUE, blue, f, p % 64, p / 64))];
        for (int b = 0; b < 16; ++b)
            flat &= abs(bins[b] - 256) <= 1;
        CHECK_MSG(flat, "frame %d: blue-noise offsets' histogram is not flat", f);
        double vb = block_mean_variance(RAYMARCH_NOISE_BLUE, blue, f), vw = block_mean_variance(RAYMARCH_NOISE_WHITE, NULL, f);
        CHECK_MSG(vb < 0.25 * vw && vw > 0.5 / (12.0 * 16.0), "frame %d: block-mean variance blue %.3g, white %.3g", f,
                  vb, vw);
    }
}

static void check_upsample(const blue_noise_texture *blue)
{
    enum { UW = 8, UH = 6 };
    float dir[3 * UW * UH] = {0}, dist[UW * UH], half[4 * 3], half_dist[4 * 3], out[UW * UH];
    for (int p = 0; p < UW * UH; ++p)
        dist[p] = p % UW < 4 ? 5.0f : 10.0f;
    for (int q = 0; q < 12; ++q)
        half_dist[q] = q % 4 < 2 ? 5.0f : 10.0f, half[q] = q % 4 < 2 ? 1.0f : 3.0f;
    raymarch_view view = {UW, UH, v3(0.0f, 0.0f, 0.0f), dir, dist};
    raymarch_upsample(half, half_dist, &view, out);
    int bleeding = 0;
    for (int p = 0; p < UW * UH; ++p)
        bleeding += out[p] != (p % UW < 4 ? 1.0f : 3.0f);
    CHECK_MSG(bleeding == 0, "%d pixels mix across the depth edge", bleeding);
    for (int f = 0; f < 8; ++f) {
        raymarch_upsample_noisy(half, half_dist, &view, blue, f, out);
        bleeding = 0;
        for (int p = 0; p < UW * UH; ++p)
            bleeding += out[p] != (p % UW < 4 ? 1.0f : 3.0f);
        CHECK_MSG(bleeding == 0, "frame %d: %d pixels of the noisy upsample mix across the depth edge", f, bleeding);
    }
    float history[2] = {1.0f, 2.0f}, next[2] = {3.0f, 2.0f};
    raymarch_accumulate(history, next, 2, 0.25, 0);
    CHECK_NEAR(history[0], 1.5, 1e-6);
    CHECK_NEAR(history[1], 2.0, 1e-6);
}

static void check_threads(const raymarch_lighting *l, const rays *r, const blue_noise_texture *blue)
{
    float a[W * H], b[W * H], ha[W * H], hb[W * H], da[W * H], db[W * H];
    raymarch_image(l, &r->view, 5, RAYMARCH_NOISE_BLUE, blue, 3, 1, a);
    raymarch_image(l, &r->view, 5, RAYMARCH_NOISE_BLUE, blue, 3, 2, b);
    raymarch_image_half(l, &r->view, 5, RAYMARCH_NOISE_IGN, blue, 3, 1, ha, da);
    raymarch_image_half(l, &r->view, 5, RAYMARCH_NOISE_IGN, blue, 3, 2, hb, db);
    CHECK(memcmp(a, b, sizeof a) == 0);
    CHECK(memcmp(ha, hb, sizeof(float) * (W / 2) * (H / 2)) == 0);
}

int main(void)
{
    const double intensity[3] = {20.0, 20.0, 20.0};
    volumetric_light spot = volumetric_spot_light(v3(0.0f, 4.0f, 0.0f), v3(0.3f, 0.0f, 0.2f), 30.0, 15.0, intensity);
    volumetric_medium medium = {0.2, 0.3, 0.4};
    static rays r;
    make_rays(&r);
    shadow_map shadows;
    blue_noise_texture blue;
    gt_error e;
    if (make_shadows(&spot, &shadows) != 0 || blue_noise_build(64, 1, 17, &blue, &e) != 0)
        return 1;
    raymarch_lighting open = {&spot, &medium, NULL, NULL}, shadowed = {&spot, &medium, &shadows, NULL};
    check_convergence(&open, &r);
    check_unbiased(&shadowed, &r, &blue);
    check_blue_noise(&blue);
    check_upsample(&blue);
    check_threads(&shadowed, &r, &blue);
    shadow_map_free(&shadows);
    blue_noise_free(&blue);
    return check_report("volumetric_light_raymarch");
}
