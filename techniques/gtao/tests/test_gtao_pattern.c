/* The GTAO talk's spatio-temporal pattern (seeds/001, "Achieving the
 * Performance Target", "Noise Distribution"): over a 4x4 tile and the
 * 24-frame cycle it visits 96 evenly spaced slice directions, each 4 times,
 * so on a static scene the tile's accumulated slices equal the brute-force
 * 96-direction integral (within float rounding), in the talk's row order and
 * in Morton order alike; the transcription's full-weight temporal rotations
 * do not (48 distinct directions). */
#include <math.h>
#include <stdlib.h>

#include "gtao/gtao.h"
#include "gtao/gtao_pattern.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

enum { TILE = 4, CYCLE = 24, DIRECTIONS = 96 };
#define PI 3.14159265358979

static int render_gbuffer(const char *spec, const char *camera_json, image *img, ss_gbuffer *g)
{
    gt_error e;
    scene s;
    camera cam;
    if (scene_load(spec, &s, &e) != 0 || camera_parse_json(camera_json, "test camera", &cam, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return -1;
    }
    reference_request req = {.quantity = QUANTITY_GBUFFER, .sampling = {.spp = 1, .seed = 7, .threads = 2},
                             .normals = NORMAL_SHADING};
    render_stats stats;
    int rc = reference_render(&s, spec, &cam, &req, img, &stats, &e);
    scene_free(&s);
    camera_view v = camera_view_from(&cam);
    ss_camera c = {v.forward, v.right, v.up, v.tan_half_yfov, v.aspect};
    if (rc != 0 || ss_gbuffer_from_image(img, spec, c, g, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return -1;
    }
    return 0;
}

/* Each k/96 visited exactly 4 times by the tile over the cycle, each time
 * with a different step offset. */
static void test_directions_visited(int pattern)
{
    int visits[DIRECTIONS] = {0}, bad_angle = 0;
    float offsets[DIRECTIONS][TILE];
    for (int y = 0; y < TILE; ++y)
        for (int x = 0; x < TILE; ++x)
            for (int f = 0; f < CYCLE; ++f) {
                double k = gtao_slice_angle(x, y, f, 0, 1, pattern) / PI * DIRECTIONS;
                int ki = (int)lround(k);
                bad_angle += fabs(k - ki) > 1e-4 || ki < 0 || ki >= DIRECTIONS;
                if (ki >= 0 && ki < DIRECTIONS && visits[ki] < TILE)
                    offsets[ki][visits[ki]] = gtao_step_offset(x, y, f, pattern);
                if (ki >= 0 && ki < DIRECTIONS)
                    ++visits[ki];
            }
    int wrong_count = 0, repeated_offset = 0;
    for (int k = 0; k < DIRECTIONS; ++k) {
        wrong_count += visits[k] != TILE;
        for (int a = 0; a < TILE && visits[k] == TILE; ++a)
            for (int b = 0; b < a; ++b)
                repeated_offset += offsets[k][a] == offsets[k][b];
    }
    printf("pattern %d: %d angles off the 96-grid, %d directions not visited 4 times, %d repeated offsets\n",
           pattern, bad_angle, wrong_count, repeated_offset);
    CHECK(bad_angle == 0 && wrong_count == 0 && repeated_offset == 0);
}

/* The transcription's temporal rotation added at full weight: directions
 * repeat (48 distinct), so the cycle cannot be the 96-direction integral. */
static void test_transcribed_rotation_repeats(void)
{
    int seen[DIRECTIONS] = {0}, distinct = 0;
    for (int y = 0; y < TILE; ++y)
        for (int x = 0; x < TILE; ++x)
            for (int f = 0; f < CYCLE; ++f) {
                double u = gtao_spatial_direction(x, y) + gtao_temporal_rotation(f);
                int k = (int)lround((u - floor(u)) * DIRECTIONS) % DIRECTIONS;
                distinct += !seen[k]++;
            }
    printf("full-weight temporal rotation: %d distinct directions\n", distinct);
    CHECK(distinct == 48);
}

static double slice_visibility(const ss_gbuffer *g, const gtao_params *p, int x, int y, float phi, float offset)
{
    gtao_slice s;
    gtao_search_slice(g, x, y, p, phi, offset, &s);
    return s.weight * s.n_len * gtao_integrate_arc_cosine(s.h1, s.h2, s.n);
}

/* Pixel (x, y)'s geometry seen with the pattern of every tile position over
 * the cycle: what the 4x4 box filter and the temporal accumulation deliver
 * when the neighbours share the pixel's geometry. full_weight: the
 * transcription's rotation. */
static double tile_cycle(const ss_gbuffer *g, const gtao_params *p, int x, int y, int full_weight)
{
    double sum = 0.0;
    for (int ty = 0; ty < TILE; ++ty)
        for (int tx = 0; tx < TILE; ++tx)
            for (int f = 0; f < CYCLE; ++f) {
                float u = gtao_pattern_direction(tx, ty, p->pattern) + gtao_temporal_rotation(f);
                float phi = full_weight ? (float)PI * (u - floorf(u)) : gtao_slice_angle(tx, ty, f, 0, 1, p->pattern);
                sum += slice_visibility(g, p, x, y, phi, gtao_step_offset(tx, ty, f, p->pattern));
            }
    return sum / (TILE * TILE * CYCLE);
}

static double brute_force(const ss_gbuffer *g, const gtao_params *p, int x, int y)
{
    double sum = 0.0;
    for (int k = 0; k < DIRECTIONS; ++k)
        sum += slice_visibility(g, p, x, y, (float)(PI * k / DIRECTIONS), 0.5f);
    return sum / DIRECTIONS;
}

/* Every 3rd pixel of the boxes seen from above, exact horizons (steps 0, so
 * step offsets do not enter): accumulation == brute force to rounding. */
static void test_accumulation_equals_brute_force(const ss_gbuffer *g, int pattern)
{
    gtao_params p;
    gtao_preset("reference", &p);
    p.slices = 1;
    p.pattern = pattern;
    p.radius = 1e4f;
    p.falloff = 0.0f;
    p.max_radius_px = 64.0f;
    double worst = 0.0, worst_transcribed = 0.0;
    for (int y = 1; y < g->height; y += 3)
        for (int x = 1; x < g->width; x += 3)
            if (ss_covered(g, x, y)) {
                double b = brute_force(g, &p, x, y);
                worst = fmax(worst, fabs(tile_cycle(g, &p, x, y, 0) - b));
                worst_transcribed = fmax(worst_transcribed, fabs(tile_cycle(g, &p, x, y, 1) - b));
            }
    printf("pattern %d: max |tile x 24 frames - 96-direction brute force| = %.3g (full-weight rotation: %.3g)\n",
           pattern, worst, worst_transcribed);
    CHECK(worst < 1e-5);
    CHECK(worst_transcribed > 1e-3);
}

/* gtao_frame with one slice is one pattern slice per pixel and frame. */
static void test_frame_is_pattern_slice(const ss_gbuffer *g)
{
    gtao_params p;
    gtao_preset("medium", &p);
    p.fast_math = 0;
    p.radius = 1e4f;
    p.falloff = 0.0f;
    float *ao = malloc(sizeof *ao * (size_t)g->width * g->height);
    double worst = 0.0;
    for (int f = 0; f < CYCLE; f += 5) {
        gtao_frame(g, &p, f, ao, NULL);
        for (int y = 0; y < g->height; y += 7)
            for (int x = 0; x < g->width; x += 5)
                if (ss_covered(g, x, y))
                    worst = fmax(worst, fabs(ao[y * g->width + x] -
                                             slice_visibility(g, &p, x, y, gtao_slice_angle(x, y, f, 0, 1, 1),
                                                              gtao_step_offset(x, y, f, 1))));
    }
    free(ao);
    printf("gtao_frame vs its pattern slice: max difference %.3g\n", worst);
    CHECK(worst < 1e-6);
}

int main(void)
{
    test_directions_visited(GTAO_PATTERN_ROWS);
    test_directions_visited(GTAO_PATTERN_MORTON);
    test_transcribed_rotation_repeats();
    image img;
    ss_gbuffer g;
    if (render_gbuffer("builtin:boxes",
                       "{\"position\":[0,26,0],\"target\":[0,0,0],\"up\":[0,0,-1],\"yfov_deg\":40,\"width\":48,"
                       "\"height\":48}",
                       &img, &g) != 0)
        return 1;
    test_accumulation_equals_brute_force(&g, GTAO_PATTERN_ROWS);
    test_accumulation_equals_brute_force(&g, GTAO_PATTERN_MORTON);
    test_frame_is_pattern_slice(&g);
    image_free(&img);
    return check_report("test_gtao_pattern");
}
