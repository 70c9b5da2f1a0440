/* Refit of Decima's EvaluateSphericalAreaGGX (SIGGRAPH 2017, appendix
 * "Spherical Area Lighting") to the Monte Carlo sphere-light reference: the
 * radius-reduction factor and the normalisation's two constants (the
 * "still in flux" formula). The model is sphere_light/sphere_light.c's own
 * decima_sphere_ggx_local with the constants as parameters (one Newton
 * step, white specular), so the fitted numbers drop straight into it.
 *
 * Residual of a configuration: ln((model + tau) / (reference + tau)) with
 * both as reflected radiance per unit normal illuminance (1/sr) and
 * tau = SPHERE_FIT_FLOOR: relative error where the highlight is, no weight
 * where the specular is far below any diffuse term (1/pi ~ 0.3 /sr). The
 * configurations are drawn from the realistic distribution of the caller,
 * so each counts once. */
#ifndef GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_FIT_H
#define GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_FIT_H

#include <stddef.h>

#include "core/error.h"
#include "core/vec3.h"
#include "sphere_light/sphere_light.h"

#define SPHERE_FIT_FLOOR 0.01

typedef struct {
    vec3 v, lc;             /* local frame, n = +z */
    float sin_sigma, alpha; /* R / d and GGX alpha */
    double reference;       /* L_spec / (pi sin^2 sigma) from the MC reference */
    double reference_stderr;
    float norm_radius;      /* the normalisation's light_radius under another reading of the appendix
                               (issue 26, item 7); 0: sin_sigma, gtlab's reading */
} sphere_light_sample;

typedef enum {
    SPHERE_MODEL_KARIS,
    SPHERE_MODEL_DECIMA,
    SPHERE_MODEL_DECIMA_HORIZON /* Decima with the terminator mended (decima_sphere_ggx_horizon_local) */
} sphere_light_model;

/* The residual of one sample under a model (k used by the DECIMA models only). */
double sphere_light_residual(sphere_light_model model, const decima_sphere_constants *k,
                             const sphere_light_sample *s);

/* Mean |residual| and root-mean-square residual over samples, each with
 * its standard error (of the mean over configurations; the RMS's by the
 * delta method). */
typedef struct {
    double mean_abs, mean_abs_stderr, rms, rms_stderr;
} sphere_light_errors;

void sphere_light_measure(sphere_light_model model, const decima_sphere_constants *k,
                          const sphere_light_sample *samples, size_t count, sphere_light_errors *out);

/* The same from residuals of any method, one at a time. */
typedef struct {
    double n, sum_abs, sum_abs2, sum_sq, sum_sq2;
} sphere_light_error_sums;
void sphere_light_error_add(sphere_light_error_sums *s, double residual);
void sphere_light_error_finish(const sphere_light_error_sums *s, sphere_light_errors *out);

/* The paired difference |residual_a| - |residual_b| over the same samples:
 * its mean and the standard error of that mean over the configurations
 * (core/statistics/sample_mean.h), so that two models' gap has an interval even where
 * their own standard errors overlap. */
void sphere_light_paired_abs(sphere_light_model a, const decima_sphere_constants *ka, sphere_light_model b,
                             const decima_sphere_constants *kb, const sphere_light_sample *samples, size_t count,
                             double *mean, double *stderr_);

/* Parameters, in order: radius_reduction, norm_scale, norm_alpha. */
#define SPHERE_FIT_PARAMS 3
/* The profile over the radius reduction: 10 coarse points 0, 0.05, ...,
 * 0.45, then 11 fine ones at 0.01 spacing around the best coarse point. */
#define SPHERE_FIT_PROFILE 21

typedef struct {
    decima_sphere_constants constants;    /* the fitted constants (others as in start) */
    double value[SPHERE_FIT_PARAMS];
    double stderr_[SPHERE_FIT_PARAMS];
    double covariance[SPHERE_FIT_PARAMS * SPHERE_FIT_PARAMS];
    int iterations, converged;
    double rmse;
    /* The cost (1/2 sum of squared residuals) with the radius reduction
     * held at each profile point and the normalisation fitted. */
    double profile_reduction[SPHERE_FIT_PROFILE], profile_cost[SPHERE_FIT_PROFILE];
    /* value[0] is the vertex of the least-squares parabola through the fine
     * profile points and stderr_[0] = sqrt(sigma^2 / k), k its curvature
     * (cost ~ 1/2 k d^2), sigma^2 = 2 cost / (m - 3) (NaN if not convex);
     * value[1..2], stderr_[1..2] and the covariance are Ceres' with the
     * radius reduction held (conditional on it). */
} sphere_light_fit_result;

/* Least squares over the training samples (central differences of step
 * 1e-3: the model is float): the profile over the radius reduction, then
 * the normalisation with it held at the profile's vertex; start supplies the normalisation's
 * starting values and the constants not fitted. threads > 1 evaluates
 * blocks in parallel (the result does not depend on it). */
int sphere_light_fit(const sphere_light_sample *samples, size_t count, const decima_sphere_constants *start,
                     int threads, sphere_light_fit_result *out, gt_error *e);

#endif
