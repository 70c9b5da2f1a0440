/* The height fog study; see height_fog.h. */
#include "height_fog/height_fog_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "core/progress.h"
#include "core/reference_schema.h"
#include "metrics/ssim.h"
#include "height_fog/height_fog_integrator.h"
#include "height_fog/height_fog_quality.h"
#include "raytracer/reference_render.h"
#include "height_fog/height_fog.h"

static const char *const weathers[2] = {"sunny", "dense"};

height_fog_request height_fog_default_request(study_quality quality)
{
    const height_fog_quality *q = height_fog_quality_of(quality);
    height_fog_request rq = {q->image_width, q->image_height, q->reference_spp, {5.0, 20.0, 60.0},
                             aerial_perspective_default_request(quality)};
    return rq;
}

/* ---- The analytic models on one view ray ------------------------------ */

typedef struct {
    float distance, camera_y, world_y, sov;
} height_fog_view;

static void run_model(const height_fog_param *p, height_fog_model m, const height_fog_view *v, float in[3], float tr[3])
{
    if (m == HEIGHT_FOG_MODEL_PUBLISHED)
        height_fog_published(p, v->distance, v->camera_y, v->world_y, v->sov, in, tr);
    else /* the models after the published one are the correction levels in order */
        height_fog_corrected(p, (height_fog_correction)(m - HEIGHT_FOG_MODEL_CLAMP_FIXED), v->distance, v->camera_y,
                             v->world_y, v->sov, in, tr);
}

/* ---- The regime table ---------------------------------------------------- */

typedef struct {
    const char *name;
    double camera_y, dir_y[2];
} regime_rays;

static const regime_rays regime_table[HEIGHT_FOG_REGIMES] = {
    {"down, camera inside the fog", 20.0, {-0.8, -0.2}},
    {"down, camera 3 km above", 3000.0, {-0.9, -0.6}},
    {"down, less than H/100 in total", 20.0, {-1e-4, -1e-3}},
    {"horizontal", 20.0, {0.0, 0.0}},
    {"up, camera inside the fog", 20.0, {0.05, 0.5}},
    {"up, camera 3 km above", 3000.0, {0.1, 0.6}},
    {"up, shallow (world point just above)", 20.0, {1e-4, 1e-3}},
    {"camera below the fog's base (y = -200 m), up", -200.0, {0.2, 0.6}},
};

static double rel_error(double a, double b)
{
    return fabs(a - b) / fmax(fabs(b), 1e-12);
}

/* One ray: the errors of both models against the quadrature. */
static void regime_ray(const height_fog_param *p, double camera_y, double dir_y, double distance,
                       height_fog_regime *r)
{
    double horizontal = sqrt(1.0 - dir_y * dir_y);
    vec3 o = v3(0.0f, (float)camera_y, 0.0f), w = v3(0.0f, (float)dir_y, (float)horizontal);
    height_fog_view v = {(float)distance, (float)camera_y, (float)(camera_y + dir_y * distance), v3_dot(p->sun_direction, w)};
    for (int ext = 0; ext <= 1; ++ext) {
        height_fog_lighting l = {p, ext, NULL, 0};
        height_fog_ray_estimate q;
        height_fog_single_scatter(&l, o, w, distance, 1e-9, &q);
        float in[3], tr[3];
        run_model(p, ext ? HEIGHT_FOG_MODEL_SUN_ATTENUATED : HEIGHT_FOG_MODEL_PUBLISHED, &v, in, tr);
        double depth = rel_error(log(fmax(tr[1], 1e-37f)), log(q.transmittance[1]));
        double l_err = q.inscatter[1] > 1e-9 ? rel_error(in[1], q.inscatter[1]) : 0.0;
        double *d = ext ? &r->corrected_depth_error : &r->published_depth_error;
        double *le = ext ? &r->corrected_l_error : &r->published_l_error;
        double tau = -log(q.transmittance[1]);
        if (tau > 1e-3 && tau < 60.0) /* where a float T resolves its optical depth */
            *d = fmax(*d, depth);
        *le = fmax(*le, l_err);
    }
}

void height_fog_regimes(height_fog_regime regimes[HEIGHT_FOG_REGIMES])
{
    const double heights[] = {10.0, 100.0, 1000.0, 1e5}, thickness[] = {1.0, 30.0, 1000.0}, distances[] = {300.0, 3000.0};
    for (int g = 0; g < HEIGHT_FOG_REGIMES; ++g) {
        height_fog_regime *r = &regimes[g];
        memset(r, 0, sizeof *r);
        snprintf(r->regime, sizeof r->regime, "%s", regime_table[g].name);
        for (int h = 0; h < 4; ++h)
            for (int t = 0; t < 3; ++t) {
                height_fog_param p;
                height_fog_weather("sunny", 25.0, &p);
                p.scale_height = heights[h];
                for (int c = 0; c < 3; ++c)
                    p.beta_rs[c] *= thickness[t];
                p.beta_ms *= thickness[t], p.beta_ma *= thickness[t];
                for (int k = 0; k < 2; ++k)
                    for (int d = 0; d < 2; ++d)
                        regime_ray(&p, regime_table[g].camera_y, regime_table[g].dir_y[k], distances[d], r);
            }
    }
}

/* The bench's view of pixel i: distances 100..4195 m, world points -50..562 m
 * below and above the camera at 30 m, every sun-view cosine. */
static height_fog_view bench_view(int i)
{
    return (height_fog_view){100.0f + (float)(i % 4096), 30.0f, (float)(i % 613) - 50.0f, (float)((i % 200) - 100) * 0.01f};
}

/* ns per pixel of the published model over n pixels in rows of HEIGHT_FOG_ROW
 * through height_fog_published_batch (the uniforms set once, per frame). */
static double time_published_batch(const height_fog_param *p, int n)
{
    enum { HEIGHT_FOG_ROW = 1024 };
    static float in[3][HEIGHT_FOG_ROW], planes[6][HEIGHT_FOG_ROW];
    for (int i = 0; i < HEIGHT_FOG_ROW; ++i) {
        height_fog_view v = bench_view(i);
        in[0][i] = v.distance, in[1][i] = v.world_y, in[2][i] = v.sov;
    }
    float *l[3] = {planes[0], planes[1], planes[2]}, *t[3] = {planes[3], planes[4], planes[5]};
    volatile float sink = 0.0f;
    double start = seconds_now();
    height_fog_uniforms u;
    height_fog_uniforms_init(p, &u);
    for (int done = 0; done < n; done += HEIGHT_FOG_ROW) {
        height_fog_published_batch(&u, 30.0f, HEIGHT_FOG_ROW, in[0], in[1], in[2], l, t);
        sink += l[0][done % HEIGHT_FOG_ROW] + t[2][done % HEIGHT_FOG_ROW];
    }
    (void)sink;
    return (seconds_now() - start) * 1e9 / (double)((n + HEIGHT_FOG_ROW - 1) / HEIGHT_FOG_ROW * HEIGHT_FOG_ROW);
}

void height_fog_time_models(int n, height_fog_timing *cost)
{
    height_fog_param p;
    height_fog_weather("dense", 20.0, &p);
    volatile float sink = 0.0f;
    for (int m = 0; m < HEIGHT_FOG_MODELS; ++m) {
        double start = seconds_now();
        for (int i = 0; i < n; ++i) {
            height_fog_view v = bench_view(i);
            float in[3], tr[3];
            run_model(&p, (height_fog_model)m, &v, in, tr);
            sink += in[0] + tr[2];
        }
        cost->ns_per_pixel[m] = (seconds_now() - start) * 1e9 / n;
    }
    (void)sink;
    cost->published_batch_ns_per_pixel = time_published_batch(&p, n);
}

/* ---- The terrain cases ----------------------------------------------------- */

static int render_fog(const scene *s, const camera *cam, height_fog_settings *fs, int spp, int threads, image *out,
                      render_stats *stats, gt_error *e)
{
    reference_request req;
    memset(&req, 0, sizeof req);
    req.quantity = &reference_quantity_fog;
    req.sampling.spp = spp;
    req.sampling.seed = 16;
    req.sampling.threads = threads;
    req.settings = &fs->header;
    return reference_render(s, "builtin:terrain", cam, &req, out, stats, e);
}

/* The analytic models' L and T planes ([model][channel]). */
typedef struct {
    float *l[HEIGHT_FOG_MODELS][3], *t[HEIGHT_FOG_MODELS][3];
} model_planes;

/* Points the planes into block (2 HEIGHT_FOG_MODELS 3 planes of n floats). */
static void model_planes_bind(model_planes *mp, float *block, size_t n)
{
    for (int m = 0; m < HEIGHT_FOG_MODELS; ++m)
        for (int c = 0; c < 3; ++c) {
            mp->l[m][c] = block + (size_t)(m * 3 + c) * n;
            mp->t[m][c] = block + (size_t)((HEIGHT_FOG_MODELS + m) * 3 + c) * n;
        }
}

static void evaluate_models(const height_fog_param *p, const image *ref, vec3 eye, model_planes *mp)
{
    const float *px = image_channel_data(ref, CH_P_X), *py = image_channel_data(ref, CH_P_Y);
    const float *pz = image_channel_data(ref, CH_P_Z), *mask = image_channel_data(ref, CH_MASK);
    for (size_t i = 0; i < image_pixel_count(ref); ++i) {
        vec3 to = v3_sub(v3(px[i], py[i], pz[i]), eye);
        float d = v3_length(to);
        height_fog_view v = {d, eye.y, py[i], d > 0.0f ? v3_dot(p->sun_direction, v3_scale(to, 1.0f / d)) : 1.0f};
        for (int m = 0; m < HEIGHT_FOG_MODELS; ++m) {
            float in[3] = {0}, tr[3] = {0};
            if (mask[i] > 0.5f)
                run_model(p, (height_fog_model)m, &v, in, tr);
            for (int c = 0; c < 3; ++c)
                mp->l[m][c][i] = in[c], mp->t[m][c][i] = tr[c];
        }
    }
}

/* sqrt of the mean over RGB and the mask of (a - b)^2. */
static double rmse_rgb(float *const a[3], const image *ref, const char *const names[3], const float *mask)
{
    double sum = 0.0;
    long n = 0;
    for (int c = 0; c < 3; ++c) {
        const float *b = image_channel_data(ref, names[c]);
        for (size_t i = 0; i < image_pixel_count(ref); ++i)
            if (mask[i] > 0.5f)
                sum += ((double)a[c][i] - b[i]) * ((double)a[c][i] - b[i]), ++n;
    }
    return n ? sqrt(sum / n) : 0.0;
}

/* sqrt of the mean over RGB and the mask of the reference's squared
 * standard errors: what an exact model's RMSE would show. */
static double noise_rms_rgb(const image *ref, const char *const names[3], const float *mask)
{
    double sum = 0.0;
    long n = 0;
    for (int c = 0; c < 3; ++c) {
        const float *se = schema_stderr_data(ref, names[c]);
        for (size_t i = 0; se && i < image_pixel_count(ref); ++i)
            if (mask[i] > 0.5f)
                sum += (double)se[i] * se[i], ++n;
    }
    return n ? sqrt(sum / n) : 0.0;
}

/* Mean of the reference, its standard error, and the single-scattering
 * comparison of the published model (green channel). */
static void reference_figures(const image *ref, const image *single, const model_planes *mp, height_fog_case *out)
{
    const float *l = image_channel_data(ref, CH_FOG_L_G), *se = image_channel_data(ref, CH_FOG_L_G ".stderr");
    const float *q = image_channel_data(single, CH_FOG_L_G), *mask = image_channel_data(ref, CH_MASK);
    double sum = 0.0, var = 0.0, sum_q = 0.0;
    int n = 0;
    out->published_max_rel_single = 0.0;
    for (size_t i = 0; i < image_pixel_count(ref); ++i) {
        if (!(mask[i] > 0.5f))
            continue;
        ++n, sum += l[i], var += (double)se[i] * se[i], sum_q += q[i];
        if (q[i] > 0.0f)
            out->published_max_rel_single = fmax(out->published_max_rel_single,
                                                 fabs(mp->l[HEIGHT_FOG_MODEL_PUBLISHED][1][i] - q[i]) / q[i]);
    }
    out->pixels = n;
    out->reference_mean_l = n ? sum / n : 0.0;
    out->reference_mean_stderr = n ? sqrt(var) / n : 0.0;
    out->single_mean_l = n ? sum_q / n : 0.0;
}

/* The error maps: published and sun-attenuated fog.L minus the reference's (green). */
static int add_error_maps(image *ref, const model_planes *mp, gt_error *e)
{
    if (!image_add_channel(ref, CH_FOG_PUBLISHED_ERROR) || !image_add_channel(ref, CH_FOG_CORRECTED_ERROR))
        return gt_error_set(e, "fog study", "out of memory");
    /* Looked up once both exist (adding a channel may move the planes). */
    const float *l = image_channel_data(ref, CH_FOG_L_G), *mask = image_channel_data(ref, CH_MASK);
    float *published = image_channel_data(ref, CH_FOG_PUBLISHED_ERROR);
    float *corrected = image_channel_data(ref, CH_FOG_CORRECTED_ERROR);
    for (size_t i = 0; i < image_pixel_count(ref); ++i) {
        float surface = mask[i] > 0.5f ? 1.0f : 0.0f; /* the models are scored on surfaces */
        published[i] = surface * (mp->l[HEIGHT_FOG_MODEL_PUBLISHED][1][i] - l[i]);
        corrected[i] = surface * (mp->l[HEIGHT_FOG_MODEL_SUN_ATTENUATED][1][i] - l[i]);
    }
    return 0;
}

/* The reference's fog.L (green) on the surfaces, 0 on the background: the
 * models are evaluated on surfaces only, so SSIM's windows at the horizon
 * must not see the sky's fog on one side alone. */
static void surface_plane(const image *ref, float *out)
{
    const float *l = image_channel_data(ref, CH_FOG_L_G), *mask = image_channel_data(ref, CH_MASK);
    for (size_t i = 0; i < image_pixel_count(ref); ++i)
        out[i] = mask[i] > 0.5f ? l[i] : 0.0f;
}

static int score_case(const height_fog_param *p, image *ref, const image *single, vec3 eye, height_fog_case *out,
                      gt_error *e)
{
    size_t n = image_pixel_count(ref);
    model_planes mp;
    float *block = calloc((2 * HEIGHT_FOG_MODELS * 3 + 1) * n, sizeof(float));
    if (!block)
        return gt_error_set(e, "fog study", "out of memory");
    model_planes_bind(&mp, block, n);
    float *reference_l = block + 2 * HEIGHT_FOG_MODELS * 3 * n;
    surface_plane(ref, reference_l);
    evaluate_models(p, ref, eye, &mp);
    const float *mask = image_channel_data(ref, CH_MASK);
    static const char *const l_names[3] = CH_FOG_L_RGB, *const t_names[3] = CH_FOG_T_RGB;
    reference_figures(ref, single, &mp, out);
    out->reference_noise_rms = noise_rms_rgb(ref, l_names, mask);
    int rc = 0;
    for (int m = 0; m < HEIGHT_FOG_MODELS && rc == 0; ++m) {
        out->rmse_l[m] = rmse_rgb(mp.l[m], ref, l_names, mask);
        out->rmse_t[m] = rmse_rgb(mp.t[m], ref, t_names, mask);
        ssim_result s;
        rc = ssim_compute(mp.l[m][1], reference_l, mask, ref->width, ref->height, "fog", NULL, &s, e);
        out->dssim_l[m] = s.dssim;
    }
    if (rc == 0)
        rc = add_error_maps(ref, &mp, e);
    free(block);
    return rc;
}

static int run_case(const study_context *ctx, const height_fog_request *rq, const scene *s, const camera *cam,
                    int weather, int sun, height_fog_case *out, gt_error *e)
{
    height_fog_settings fs = {.header = {&reference_quantity_fog}, .sun_elevation_deg = rq->sun_elevations[sun],
                       .scattering = HEIGHT_FOG_MULTIPLE, .max_scatterings = 1024};
    snprintf(fs.weather, sizeof fs.weather, "%s", weathers[weather]);
    snprintf(out->weather, sizeof out->weather, "%s", weathers[weather]);
    out->sun_elevation_deg = rq->sun_elevations[sun];
    image ref, single;
    render_stats stats, single_stats;
    if (render_fog(s, cam, &fs, rq->spp, ctx->threads, &ref, &stats, e) != 0)
        return -1;
    out->reference_rays_per_second = stats.seconds > 0.0 ? (double)stats.rays / stats.seconds : 0.0;
    height_fog_settings single_fs = fs;
    single_fs.scattering = HEIGHT_FOG_QUADRATURE, single_fs.no_sun_extinction = 1, single_fs.no_shadows = 1;
    if (render_fog(s, cam, &single_fs, 1, ctx->threads, &single, &single_stats, e) != 0) {
        image_free(&ref);
        return -1;
    }
    height_fog_param p;
    height_fog_weather(fs.weather, fs.sun_elevation_deg, &p);
    int rc = score_case(&p, &ref, &single, cam->position, out, e);
    char dir[2048], path[2300];
    if (rc == 0 && (rc = study_make_dir(ctx, HEIGHT_FOG_DIR, dir, sizeof dir, e)) == 0) {
        snprintf(path, sizeof path, "%s/%s_sun%02d.exr", dir, fs.weather, (int)fs.sun_elevation_deg);
        rc = exr_write(path, &ref, e);
    }
    image_free(&ref);
    image_free(&single);
    return rc;
}

int height_fog_study(const study_context *ctx, const height_fog_request *rq, height_fog_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->request = *rq;
    scene s;
    camera cam;
    if (study_load_view("builtin:terrain", rq->width, rq->height, &s, &cam, e) != 0)
        return -1;
    int rc = 0;
    for (int w = 0; w < 2 && rc == 0; ++w)
        for (int k = 0; k < HEIGHT_FOG_SUNS && rc == 0; ++k)
            rc = run_case(ctx, rq, &s, &cam, w, k, &out->cases[w * HEIGHT_FOG_SUNS + k], e);
    scene_free(&s);
    if (rc != 0)
        return -1;
    height_fog_regimes(out->regimes);
    height_fog_time_models(1 << 20, &out->analytic_cost);
    char dir[2048];
    if (study_make_dir(ctx, HEIGHT_FOG_DIR, dir, sizeof dir, e) != 0)
        return -1;
    return aerial_perspective_study(ctx, dir, &rq->aerial, &out->aerial, e);
}

int height_fog_approx_image(const image *gbuffer, const char *what, const char *weather, double sun_elevation_deg,
                            height_fog_model m, image *out, gt_error *e)
{
    height_fog_param p;
    camera cam;
    const char *camera_json = image_get_attribute(gbuffer, ATTR_CAMERA);
    if (height_fog_weather(weather, sun_elevation_deg, &p) != 0)
        return gt_error_set(e, "--weather", "'%s' is neither sunny nor dense", weather);
    if (!camera_json || camera_parse_json(camera_json, what, &cam, e) != 0)
        return camera_json ? -1 : gt_error_set(e, what, "no camera in the header");
    if (!image_channel_data(gbuffer, CH_P_X) || !image_channel_data(gbuffer, CH_MASK))
        return gt_error_set(e, what, "missing channel %s or %s (a render gbuffer or fog file)", CH_P_X, CH_MASK);
    size_t n = image_pixel_count(gbuffer);
    float *block = calloc(2 * HEIGHT_FOG_MODELS * 3 * n, sizeof(float));
    if (!block || image_init(out, gbuffer->width, gbuffer->height) != 0) {
        free(block);
        return gt_error_set(e, what, "out of memory");
    }
    model_planes mp;
    model_planes_bind(&mp, block, n);
    evaluate_models(&p, gbuffer, cam.position, &mp);
    static const char *const l_names[3] = CH_FOG_L_RGB, *const t_names[3] = CH_FOG_T_RGB;
    int rc = 0;
    for (int c = 0; c < 3 && rc == 0; ++c) {
        float *l = image_add_channel(out, l_names[c]), *t = image_add_channel(out, t_names[c]);
        if (!l || !t)
            rc = gt_error_set(e, what, "out of memory");
        for (size_t i = 0; rc == 0 && i < n; ++i)
            l[i] = mp.l[m][c][i], t[i] = mp.t[m][c][i];
    }
    free(block);
    return rc;
}

int height_fog_bench(int threads, double *rays_per_second, height_fog_timing *cost, gt_error *e)
{
    scene s;
    camera cam;
    if (study_load_view("builtin:terrain", 128, 96, &s, &cam, e) != 0)
        return -1;
    height_fog_settings fs = {.header = {&reference_quantity_fog}, .weather = "dense", .sun_elevation_deg = 20.0,
                       .scattering = HEIGHT_FOG_MULTIPLE, .max_scatterings = 1024};
    image img;
    render_stats stats;
    int rc = render_fog(&s, &cam, &fs, 16, threads, &img, &stats, e);
    scene_free(&s);
    if (rc != 0)
        return -1;
    image_free(&img);
    *rays_per_second = stats.seconds > 0.0 ? (double)stats.rays / stats.seconds : 0.0;
    height_fog_time_models(1 << 22, cost);
    return 0;
}

void height_fog_bench_print(FILE *f, double rays_per_second, const height_fog_timing *cost)
{
    const double *ns = cost->ns_per_pixel;
    fprintf(f, "reference: %.3g rays/s\nanalytic: %.2f ns/pixel published, %.2f clamp fixed, %.2f sun attenuated, "
               "%.2f sky attenuated (one pixel at a time)\npublished, batched over rows (vectorised): %.2f ns/pixel "
               "(%.1fx)\n", rays_per_second, ns[0], ns[1], ns[2], ns[3], cost->published_batch_ns_per_pixel,
            ns[0] / cost->published_batch_ns_per_pixel);
}
