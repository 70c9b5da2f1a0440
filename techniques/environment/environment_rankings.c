/* The environment study's statistics (environment/environment_study.h): the
 * specular-occlusion ranking under each environment against the white
 * dome's, and the figures of the GTAO talk's claim, from the per-scene
 * figures alone. */
#include <math.h>

#include "metrics/noise_corrected.h"
#include "environment/environment_study.h"

static const char *const so_labels[ENVIRONMENT_STUDY_SO_VARIANTS] = {"ao", "lagarde", "cone-exact:exp2-alpha", "lut",
                                                             "cone-horizon:exp2-alpha", "sg"};
const char *environment_study_so_label(int variant)
{
    return variant >= 0 && variant < ENVIRONMENT_STUDY_SO_VARIANTS ? so_labels[variant] : "?";
}

const char *environment_error_part_name(environment_error_part p)
{
    static const char *const names[ENVIRONMENT_PARTS] = {"lighting", "occlusion", "total"};
    return p >= 0 && p < ENVIRONMENT_PARTS ? names[p] : "?";
}

/* Mean and standard error of the mean of a[i] - b[i] (b NULL: of a) over n scenes. */
static environment_paired paired(const double *a, const double *b, int n)
{
    environment_paired r = {0.0, NAN, n};
    double sum = 0.0, sq = 0.0;
    for (int i = 0; i < n; ++i) {
        double d = a[i] - (b ? b[i] : 0.0);
        sum += d, sq += d * d;
    }
    r.mean = n ? sum / n : NAN;
    if (n > 1)
        r.standard_error = sqrt(fmax(0.0, (sq - n * r.mean * r.mean) / (n - 1)) / n);
    return r;
}

static int significant(environment_paired p) { return fabs(p.mean) > 2.0 * p.standard_error; }

/* The order of the variants by mean total relative RMSE, and its agreement with the white dome's. */
void environment_study_rank(environment_study_result *out, int env)
{
    environment_so_ranking *r = &out->rankings[env];
    const environment_study_environment *x = &out->environments[env], *w = &out->environments[0];
    for (int v = 0; v < ENVIRONMENT_STUDY_SO_VARIANTS; ++v) {
        int place = 0;
        for (int u = 0; u < ENVIRONMENT_STUDY_SO_VARIANTS; ++u)
            place += x->specular[u][ENVIRONMENT_PART_TOTAL].rmse < x->specular[v][ENVIRONMENT_PART_TOTAL].rmse ||
                     (x->specular[u][ENVIRONMENT_PART_TOTAL].rmse == x->specular[v][ENVIRONMENT_PART_TOTAL].rmse && u < v);
        r->order[place] = v;
    }
    int concordant = 0, discordant = 0, n = out->scene_count;
    r->flipped_pairs = r->significant_flips = 0;
    for (int a = 0; a < ENVIRONMENT_STUDY_SO_VARIANTS; ++a)
        for (int b = a + 1; b < ENVIRONMENT_STUDY_SO_VARIANTS; ++b) {
            environment_paired pw = paired(w->specular_case[a], w->specular_case[b], n);
            environment_paired px = paired(x->specular_case[a], x->specular_case[b], n);
            int same = (pw.mean < 0) == (px.mean < 0);
            concordant += same, discordant += !same;
            r->flipped_pairs += !same;
            r->significant_flips += !same && significant(pw) && significant(px);
        }
    r->kendall_tau = (double)(concordant - discordant) / (concordant + discordant);
}

/* The talk's claim: the occlusion part of AO x E(n) (map) under the white
 * dome, and under the environment where it is smallest. */
void environment_study_claim(environment_study_result *out)
{
    int n = out->scene_count;
    double corrected[ENVIRONMENT_STUDY_MAX_ENVIRONMENTS][ENVIRONMENT_STUDY_MAX_SCENES];
    for (int env = 0; env < out->environment_count; ++env)
        for (int s = 0; s < n; ++s) {
            const environment_study_environment *x = &out->environments[env];
            corrected[env][s] = noise_corrected_rmse(x->ao_n_case[ENVIRONMENT_PART_OCCLUSION][s],
                                                     x->noise_case[s] * x->noise_case[s]);
        }
    out->white_occlusion = paired(corrected[0], NULL, n);
    out->claim_environment = -1;
    for (int env = 1; env < out->environment_count; ++env) {
        environment_paired p = paired(corrected[env], NULL, n);
        if (out->claim_environment < 0 || p.mean < out->other_occlusion.mean)
            out->claim_environment = env, out->other_occlusion = p;
    }
}
