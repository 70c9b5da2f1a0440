/* The AO and bent-normal references of every built-in scene (the `ao` stage
 * of `gtlab all`): cosine-weighted AO V_d = (1/pi) \int V(w) (n.w) dw over
 * the hemisphere, uniform AO and the bent normal, at the surface seen through
 * each pixel centre, from Owen-scrambled Sobol' samples; per-pixel standard
 * errors from the samples themselves, and the noise floor: the DSSIM between
 * the AO of the even and of the odd samples, below which no approximation
 * can be scored.
 *
 * Writes <output>/ao/<scene>.exr with <scene>.camera.json (the inputs of the
 * screen-space studies) and <output>/figures/{ao,bent,ao_stderr}_<scene>.png. */
#ifndef GTLAB_AO_AO_REFERENCES_H
#define GTLAB_AO_AO_REFERENCES_H

#include <stdint.h>

#include "project/study_context.h"
#include "project/scene_list.h"

/* The folder below the output folder that holds the references. */
#define AO_REFERENCES_DIR "ao"

enum { AO_REFERENCES_MAX_SCENES = STUDY_SCENES_MAX };

typedef struct {
    char scene[64];
    uint64_t triangles;
    int width, height, covered_pixels;
    double seconds, rays_per_second, mean_spp;
    double mean_stderr, max_stderr; /* of ao.V over the covered pixels */
    double noise_rmse;              /* sqrt(mean stderr^2): the noise a figure against it carries */
    double noise_floor_dssim;       /* even vs odd samples */
} ao_reference_row;

typedef struct {
    int size;             /* image width (the height follows the scene's camera) */
    int spp;              /* samples per pixel (the most with a target) */
    double target_stderr; /* the noise budget a pixel stops at; 0: every pixel takes spp samples */
    uint32_t seed;
    int scene_count;      /* the first scene_count built-in scenes; 0: all */
} ao_references_request;

typedef struct {
    ao_references_request request;
    int count;
    ao_reference_row rows[AO_REFERENCES_MAX_SCENES]; /* study_scene_at order */
} ao_references_result;

/* The request of `gtlab all` at a quality: its image width, samples per
 * pixel and target standard error are the quality table's (ao rows of
 * techniques/quality_table.txt); seed 1, every built-in scene. */
ao_references_request ao_references_default_request(study_quality quality);

int ao_references_study(const study_context *ctx, const ao_references_request *rq, ao_references_result *out,
                        gt_error *e);

#endif
