/* The volumetric-light study (issue 29; INSIDE, Gjoel & Svendsen, GDC 2016,
 * seed 002): the ray-march of volumetric_light/volumetric_light_raymarch.h against the
 * single-scattering reference (techniques/volumetric_light/volumetric_light_integral.h) on
 * builtin:cornell with the default spot of `gtlab render volumetric-light`,
 * the tall block's shadow cutting a shaft.
 *
 * Errors are over the pixels that see a surface, of L / I (grey): RMSE
 * relative to the reference's mean; the same after a Gaussian blur of
 * sigma 1 pixel of both images (over the surface pixels), the error a
 * viewer or TAA's neighbourhood sees once the finest noise is averaged,
 * where a noise's spectrum matters; and DSSIM (both images scaled by 1 / the
 * reference's 99th percentile). Per noise type (none, white,
 * Bayer 8x8, IGN, blue) and samples per pixel (steps per ray):
 *   single       frame 0 of each seed;
 *   accumulated  the exponential history (alpha) after `frames` frames.
 * A seed k moves the start frame to 1009 k (white: other streams; Bayer,
 * IGN, blue: another golden-ratio shift) and builds the blue-noise texture
 * with seed 1 + k; figures are means over the seeds with their standard
 * errors. The target is the error of 128 uniform steps (no noise); the spp
 * each noise needs to reach it is interpolated in log-log between the
 * sampled counts (infinite when the largest count does not reach it). The
 * talk's final configuration is half resolution, blue noise, the
 * depth-aware upsample (bilinear taps, and the talk's noisy taps) and
 * accumulation, at 3, 6 and 9 samples per half-resolution pixel. The shadow map (512^2 unless varied) is a measured
 * factor: the error of a 1024-step march (offset 1/2) per map size is its
 * floor.
 *
 * Structure (the error a blur cannot see): the error of frame 0 at 3 spp
 * (image minus reference, 0 off the surface pixels) through the
 * periodogram's peak ratio (metrics/dither_metrics.h: a periodic pattern's
 * error piles into a few frequencies), per noise, mean over the seeds, and
 * Bayer's and IGN's over blue's per seed.
 *
 * Equal cost (issue 42): at cost_width x cost_height (at least 512^2; the
 * reference's tolerance cost_reference_rel_tol) the talk's configuration (6
 * blue-noise samples per half-resolution pixel, the noisy depth-aware
 * upsample, the frames accumulated; 1.5 samples per pixel) against the
 * uniform march it replaces at no smaller cost, 2 uniform steps per pixel
 * (and 24, the talk's 3.6 ms slide), by DSSIM and by mean FLIP (flip_grey
 * of the images as SSIM sees them, scaled by 1 / the reference's 99th
 * percentile: HDR-FLIP with the reference's exposures where values exceed
 * 1, so the figure does not depend on the light's units); each gap paired
 * per seed. */
#ifndef GTLAB_VOLUMETRIC_LIGHT_STUDY_H
#define GTLAB_VOLUMETRIC_LIGHT_STUDY_H

#include "core/image.h"
#include "volumetric_light/volumetric_light_raymarch.h"
#include "project/study_context.h"

#define VOLUMETRIC_LIGHT_DIR "volumetric_light"
enum { VOLUMETRIC_LIGHT_MAX_SPP = 16, VOLUMETRIC_LIGHT_MAX_SEEDS = 8, VOLUMETRIC_LIGHT_SHADOW_SIZES = 4, VOLUMETRIC_LIGHT_TALK_SPP = 3 };

typedef struct {
    int width, height;
    int seeds, frames;
    double alpha;       /* the history's weight of a new frame */
    int shadow_size;    /* the shadow map of the noise measurements */
    double shadow_bias; /* relative */
    int spp_count;
    int spp[VOLUMETRIC_LIGHT_MAX_SPP];
    int blue_noise_size;
    double reference_rel_tol;
    int cost_width, cost_height;  /* the equal-cost comparison's image */
    double cost_reference_rel_tol;
} volumetric_light_request;

typedef struct {
    double rmse, rmse_se;   /* relative RMSE, mean over seeds and its standard error */
    double dssim, dssim_se;
    double blurred, blurred_se; /* relative RMSE after a Gaussian blur (sigma 1 pixel) of both images */
    double flip, flip_se;       /* mean FLIP (metrics/flip.h, flip_grey) of the scaled images; equal cost only, else 0 */
} volumetric_light_error;

typedef struct {
    volumetric_light_request request;
    int pixels;
    double reference_mean, reference_max_error; /* mean L / I; largest quadrature error estimate over it */
    double reference_seconds;
    long reference_rays;
    volumetric_light_error single[RAYMARCH_NOISE_COUNT][VOLUMETRIC_LIGHT_MAX_SPP];
    volumetric_light_error accumulated[RAYMARCH_NOISE_COUNT][VOLUMETRIC_LIGHT_MAX_SPP];
    volumetric_light_error uniform128;                        /* none, 128 steps, one frame: the target */
    /* each seed's relative RMSE at 3 spp, frames accumulated: the jitter
     * patterns' gaps paired over the seeds */
    double rmse3_accumulated_by_seed[RAYMARCH_NOISE_COUNT][VOLUMETRIC_LIGHT_MAX_SEEDS];
    double spp_needed_single[RAYMARCH_NOISE_COUNT]; /* to reach uniform128's RMSE; INFINITY: not reached */
    double spp_needed_accumulated[RAYMARCH_NOISE_COUNT];
    int talk_spp[VOLUMETRIC_LIGHT_TALK_SPP];                  /* 3, 6, 9 at half resolution */
    volumetric_light_error talk[VOLUMETRIC_LIGHT_TALK_SPP];             /* half res, blue, upsampled, accumulated */
    volumetric_light_error talk_single[VOLUMETRIC_LIGHT_TALK_SPP];      /* the same, frame 0 alone */
    volumetric_light_error talk_noisy[VOLUMETRIC_LIGHT_TALK_SPP];       /* with the talk's noisy upsample, accumulated */
    int shadow_sizes[VOLUMETRIC_LIGHT_SHADOW_SIZES];
    double shadow_rmse[VOLUMETRIC_LIGHT_SHADOW_SIZES];        /* relative RMSE of 1024 midpoint steps */
    double shadow_seconds[VOLUMETRIC_LIGHT_SHADOW_SIZES];
    /* blue over white, Bayer, IGN at 3 spp: ratios of the accumulated RMSE and of the single frame's
     * blurred RMSE, means over the seeds of the per-seed ratios, with standard errors */
    double blue_ratio[RAYMARCH_NOISE_COUNT], blue_ratio_se[RAYMARCH_NOISE_COUNT];
    double blue_blurred_ratio[RAYMARCH_NOISE_COUNT], blue_blurred_ratio_se[RAYMARCH_NOISE_COUNT];
    double ns_per_pixel_sample;                     /* the ray-march, one thread */
    /* blue's single-frame blurred relative RMSE minus each noise's at 3 spp, mean of the per-seed gaps */
    double blue_blurred_gap[RAYMARCH_NOISE_COUNT], blue_blurred_gap_se[RAYMARCH_NOISE_COUNT];
    /* the 3-spp frame-0 error's periodogram peak ratio per noise, and each over blue's (per-seed ratios) */
    double peak_ratio[RAYMARCH_NOISE_COUNT], peak_ratio_se[RAYMARCH_NOISE_COUNT];
    double peak_over_blue[RAYMARCH_NOISE_COUNT], peak_over_blue_se[RAYMARCH_NOISE_COUNT];
    /* equal cost at cost_width x cost_height: the talk's configuration (accumulated), uniform 2 and 24 steps */
    int cost_pixels;
    double cost_reference_seconds;
    volumetric_light_error cost_talk, cost_uniform2, cost_uniform24;
    double cost_dssim_gap, cost_dssim_gap_se; /* DSSIM(talk) - DSSIM(uniform 2), per seed */
    double cost_flip_gap, cost_flip_gap_se;   /* FLIP(talk) - FLIP(uniform 2), per seed */
} volumetric_light_result;

/* The request of `gtlab all` at a quality: its image size, seeds, frames,
 * blue-noise size and equal-cost image are the quality table's
 * (volumetric_light rows of techniques/quality_table.txt). */
volumetric_light_request volumetric_light_default_request(study_quality quality);
/* Runs the study; writes <output>/volumetric/ (reference and image strip
 * PNGs, plot data). Returns 0 or -1 with e. */
int volumetric_light_study(const study_context *ctx, const volumetric_light_request *rq, volumetric_light_result *out, gt_error *e);

/* The ray-march's cost on the study's view: ns per pixel per sample (one
 * thread, `steps` steps, blue noise, shadow map 512^2). */
int volumetric_light_bench(int width, int height, int steps, double *ns_per_pixel_sample, gt_error *e);

/* `gtlab approx raymarch`: the ray-march of one configuration on the
 * study's view (builtin:cornell, width x height), accumulated over `frames`
 * frames (1: a single frame), into out's vlight.L.R/G/B (radiance: the
 * light's intensity times L / I). Returns 0 or -1 with e. */
typedef struct {
    int width, height, steps, frames, half, shadow_size, threads; /* half: 0 full, 1 bilinear, 2 noisy upsample */
    raymarch_noise noise;
    double alpha;
} volumetric_light_approx_request;

int volumetric_light_approx_image(const volumetric_light_approx_request *rq, image *out, gt_error *e);

#endif
