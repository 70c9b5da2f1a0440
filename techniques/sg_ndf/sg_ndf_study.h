/* The NDF fit with spherical Gaussians (issue 18 item 4; Kaplanyan,
 * CryENGINE 3, SIGGRAPH 2010: "need only ~7 lobes for anisotropic Ward
 * NDF"). For anisotropic Ward and GGX over a grid of roughness pairs, the
 * greedy series of k = 1..max_lobes SG fits (sg_ndf/sg_ndf_fit.h: solid-
 * angle-weighted least squares in D, relative L2 and max errors), and for
 * the image materials the specular images of the true NDF and of each
 * k-lobe sum (sg_ndf/sg_ndf_images.h) scored by DSSIM against the true
 * NDF's, beside the true image's own noise floor (DSSIM of its two
 * independent halves).
 *
 * Writes under <output>/sg_ndf/: sg_ndf_lobes.json and sg_ndf_lobes.h (every
 * fitted lobe: material, k, status, errors, axis, sharpness, amplitude and
 * their standard errors), sg_ndf_error.dat (E and max error against k per
 * material, for the plot), and per image material true.png and k<N>.png
 * (exposure 1, sRGB). */
#ifndef GTLAB_SG_NDF_STUDY_H
#define GTLAB_SG_NDF_STUDY_H

#include "core/optics/anisotropic_ndf.h"
#include "sg_ndf/sg_ndf_fit.h"
#include "project/study_context.h"

#define SG_NDF_DIR "sg_ndf"
enum { SG_NDF_MATERIALS = 16, SG_NDF_STUDY_LOBES = 9 };

typedef struct {
    int material_count;
    anisotropic_ndf materials[SG_NDF_MATERIALS];
    int imaged[SG_NDF_MATERIALS]; /* 1: render and score its images */
    int max_lobes;                /* <= SG_NDF_STUDY_LOBES */
    sg_fit_options fit;
    int image_size, image_samples;
    unsigned seed;
    double l2_target;             /* "enough lobes": the least k with E below it */
} sg_ndf_request;

/* The request of `gtlab all` at a quality: its (alpha_x, alpha_y) pairs (for
 * both NDFs), the fit's grid and the images' side and samples are the quality
 * table's (sg_ndf rows of techniques/quality_table.txt). */
sg_ndf_request sg_ndf_default_request(study_quality quality);

typedef struct {
    anisotropic_ndf ndf;
    sg_fit fits[SG_NDF_STUDY_LOBES];
    int fitted;              /* fits with status OK: k = 1..fitted */
    int lobes_for_target;    /* least k with E <= l2_target, 0 if none among the OK fits */
    int has_images;
    double dssim[SG_NDF_STUDY_LOBES]; /* SG sum's image against the true one, per k (0 where not fitted) */
    double noise_floor_dssim;         /* the true image's halves */
    double mean_relative_stderr;      /* mean over sphere pixels of se / mean of the true image */
} sg_ndf_material;

typedef struct {
    sg_ndf_request request;
    sg_ndf_material materials[SG_NDF_MATERIALS];
    double seconds;
} sg_ndf_result;

/* Runs the study; 0, or -1 with e (a fit or a file could not be made). */
int sg_ndf_study(const study_context *ctx, const sg_ndf_request *rq, sg_ndf_result *r, gt_error *e);

#endif
