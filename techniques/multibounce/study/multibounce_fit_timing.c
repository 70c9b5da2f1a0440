#include "multibounce/multibounce_fit_timing.h"

#include <math.h>
#include <stdint.h>

#include "core/progress.h"
#include "multibounce/multibounce_fit.h"

/* A uniform number in [-0.5, 0.5) from a hash of i: the synthetic noise. */
static double hashed_noise(uint64_t i)
{
    i = (i ^ (i >> 30)) * 0xBF58476D1CE4E5B9ull;
    i = (i ^ (i >> 27)) * 0x94D049BB133111EBull;
    i ^= i >> 31;
    return (double)(i >> 11) * 0x1p-53 - 0.5;
}

static int synthesise(multibounce_data *d, long n, gt_error *e)
{
    static const float albedos[7] = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.7f, 0.9f};
    const multibounce_model truth = multibounce_model_jimenez2016(); /* any smooth curve serves a timing */
    int scene = multibounce_data_scene(d, "synthetic", e);
    for (long i = 0; i < n; ++i) {
        int a = multibounce_data_albedo(d, albedos[i % 7], e);
        double v = ((double)(i / 7) + 0.5) / (double)((n + 6) / 7);
        double y = gtao_multibounce(&truth, v, albedos[i % 7]) + 0.02 * hashed_noise((uint64_t)i);
        if (scene < 0 || a < 0 || multibounce_data_push(d, scene, a, (float)v, (float)y, e) != 0)
            return -1;
    }
    multibounce_data_weigh(d);
    return 0;
}

/* The best of `repeats` fits with blocks of t->block_size. */
static int time_fit(const multibounce_data *d, long repeats, multibounce_fit_timing *t, gt_error *e)
{
    const multibounce_fit_options o = {t->block_size, 0};
    multibounce_fit f;
    t->best_seconds = INFINITY;
    for (long r = 0; r < repeats; ++r) {
        double t0 = seconds_now();
        if (multibounce_fit_model(d, 1, &o, &f, e) != 0)
            return -1;
        t->best_seconds = fmin(t->best_seconds, seconds_now() - t0);
    }
    t->solve_seconds = f.solver.seconds;
    t->iterations = f.solver.iterations;
    return 0;
}

int multibounce_fit_timing_run(long samples, long repeats, multibounce_fit_timing out[MULTIBOUNCE_FIT_TIMINGS],
                               gt_error *e)
{
    static const int block_sizes[MULTIBOUNCE_FIT_TIMINGS] = {1, MBFIT_DEFAULT_BLOCK};
    multibounce_data d;
    multibounce_data_init(&d);
    int rc = synthesise(&d, samples, e);
    for (int b = 0; b < MULTIBOUNCE_FIT_TIMINGS && rc == 0; ++b) {
        out[b] = (multibounce_fit_timing){.block_size = block_sizes[b]};
        rc = time_fit(&d, repeats, &out[b], e);
    }
    multibounce_data_free(&d);
    return rc;
}
