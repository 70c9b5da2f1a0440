/* The shortcut studies of issue 25, items 6-8, on one scene, and the
 * 24-frame cycle items 7 and 8 observe; see gtao_shortcuts.h. */
#include "gtao/gtao_shortcuts.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gtao/gtao_denoiser.h"
#include "gtao/gtao_pattern.h"
#include "gtao/gtao_spatial_filter.h"
#include "gtao/gtao_talk_setting.h"

const float gtao_clamp_windows[GTAO_CLAMP_WINDOWS] = {0.0f, 0.25f, 0.5f, 1.0f, 2.0f};

gtao_params gtao_cycle_params(const gtao_shortcut_scene *s, int pattern)
{
    gtao_params p;
    gtao_preset("medium", &p);
    p.radius = s->radius;
    p.falloff = s->falloff;
    p.max_radius_px = s->max_radius_px;
    p.pattern = pattern;
    p.frames = 1;
    return p;
}

/* The cycle's planes. */
enum {
    BRUTE, RAW, FILTERED, FIXED_FILTERED, FIRST, LAST = FIRST + GTAO_CYCLE_ORDERS, RAW_FIRST = LAST + GTAO_CYCLE_ORDERS,
    RAW_ACC, FIXED_ACC, CLAMPED, PLANES = CLAMPED + GTAO_CLAMP_WINDOWS
};

static int brute_force(const gtao_shortcut_scene *s, float *ao)
{
    gtao_params p = gtao_cycle_params(s, GTAO_PATTERN_OFF);
    p.slices = GTAO_PATTERN_DIRECTIONS;
    p.denoise = 0;
    return gtao_render(s->g, &p, ao, NULL);
}

/* The rows order's extra observers: no filter, a fixed window, clamped histories. */
static void rows_observers(const ss_gbuffer *g, int f, float **b)
{
    size_t n = (size_t)g->width * g->height;
    if (f == 0)
        memcpy(b[RAW_FIRST], b[RAW], sizeof(float) * n);
    gtao_temporal_accumulate(b[RAW], f, n, b[RAW_ACC]);
    gtao_spatial_options fixed = gtao_spatial_default;
    fixed.alternate = 0;
    gtao_spatial_filter(g, f, &fixed, b[RAW], b[FIXED_FILTERED]);
    gtao_temporal_accumulate(b[FIXED_FILTERED], f, n, b[FIXED_ACC]);
    for (int k = 0; k < GTAO_CLAMP_WINDOWS; ++k)
        gtao_temporal_clamped(g, b[FILTERED], f, gtao_clamp_windows[k], b[CLAMPED + k]);
}

static void run_cycle(const gtao_shortcut_scene *s, float **b)
{
    const ss_gbuffer *g = s->g;
    size_t n = (size_t)g->width * g->height;
    for (int order = 0; order < GTAO_CYCLE_ORDERS; ++order) {
        gtao_params p = gtao_cycle_params(s, order == 0 ? GTAO_PATTERN_ROWS : GTAO_PATTERN_MORTON);
        for (int f = 0; f < GTAO_CYCLE_FRAMES; ++f) {
            gtao_frame(g, &p, f, b[RAW], NULL);
            gtao_spatial_filter(g, f, &gtao_spatial_default, b[RAW], b[FILTERED]);
            gtao_temporal_accumulate(b[FILTERED], f, n, b[LAST + order]);
            if (f == 0)
                memcpy(b[FIRST + order], b[LAST + order], sizeof(float) * n);
            if (order == 0)
                rows_observers(g, f, b);
        }
    }
}

static gtao_cycle cycle_view(float **b)
{
    gtao_cycle c = {.brute = b[BRUTE], .raw_last = b[RAW_ACC], .raw_first = b[RAW_FIRST],
                    .fixed_window_last = b[FIXED_ACC]};
    for (int order = 0; order < GTAO_CYCLE_ORDERS; ++order) {
        c.first[order] = b[FIRST + order];
        c.last[order] = b[LAST + order];
    }
    for (int k = 0; k < GTAO_CLAMP_WINDOWS; ++k)
        c.clamped_last[k] = b[CLAMPED + k];
    return c;
}

static int cycle_studies(const gtao_shortcut_scene *s, float **b, gtao_pattern_result *pattern,
                         gtao_denoisers_result *denoisers, gt_error *e)
{
    if (brute_force(s, b[BRUTE]) != 0)
        return gt_error_set(e, s->name, "out of memory");
    run_cycle(s, b);
    gtao_cycle c = cycle_view(b);
    if (gtao_pattern_scene_study(s, &c, pattern, e) != 0)
        return -1;
    return gtao_denoisers_scene_study(s, &c, denoisers, e);
}

/* The cycle of s observed by the pattern and denoiser studies. */
static int cycle_scene(const gtao_shortcut_scene *s, gtao_pattern_result *pattern, gtao_denoisers_result *denoisers,
                       gt_error *e)
{
    size_t n = (size_t)s->g->width * s->g->height;
    float *storage = malloc(sizeof(float) * n * PLANES), *b[PLANES];
    if (!storage)
        return gt_error_set(e, s->name, "out of memory");
    for (int k = 0; k < PLANES; ++k)
        b[k] = storage + (size_t)k * n;
    int rc = cycle_studies(s, b, pattern, denoisers, e);
    free(storage);
    return rc;
}

int gtao_shortcuts_scene(const gtao_shortcut_scene *s, gtao_shortcuts_result *r, gt_error *e)
{
    if (cycle_scene(s, &r->pattern, &r->denoisers, e) != 0)
        return -1;
    return gtao_half_res_scene_study(s, &r->half_res, e);
}

int gtao_shortcuts_talk_scene(const char *name, const ss_gbuffer *full, const ss_gbuffer *half,
                              float camera_distance, gtao_talk_result *r, gt_error *e)
{
    if (r->scene_count == GTAO_TALK_MAX_SCENES)
        return gt_error_set(e, name, "more than %d scenes in the talk's setting", GTAO_TALK_MAX_SCENES);
    snprintf(r->scenes[r->scene_count++], sizeof r->scenes[0], "%s", name);
    r->full_width = full->width, r->full_height = full->height;
    r->half_width = half->width, r->half_height = half->height;
    gtao_params talk = {0};
    gtao_talk_radius(camera_distance, half, &talk);
    gtao_shortcut_scene f = {.name = name, .g = full, .radius = talk.radius, .max_radius_px = (float)full->width,
                             .camera_distance = camera_distance, .claim_radius_only = 1,
                             .no_four_x = 1, .falloff = talk.falloff};
    gtao_shortcut_scene h = f;
    h.g = half;
    h.max_radius_px = talk.max_radius_px;
    h.no_four_x = 0;
    int rc = gtao_half_res_scene_study(&f, &r->half_res, e) != 0 || gtao_half_res_scene_study(&h, &r->half_pass, e) != 0 ||
                     cycle_scene(&h, &r->pattern, &r->denoisers, e) != 0
                 ? -1
                 : 0;
    return rc;
}

void gtao_shortcuts_finish(gtao_shortcuts_result *r)
{
    gtao_pattern_finish(&r->pattern);
    gtao_half_res_finish(&r->half_res);
    gtao_denoisers_finish(&r->denoisers);
    gtao_pattern_finish(&r->talk.pattern);
    gtao_half_res_finish(&r->talk.half_res);
    gtao_half_res_finish(&r->talk.half_pass);
    gtao_denoisers_finish(&r->talk.denoisers);
}
