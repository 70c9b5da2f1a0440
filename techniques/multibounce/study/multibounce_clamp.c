/* The shader's clamp max(V_d, cubic) (multibounce/multibounce_study.h,
 * multibounce_clamp): where the talk's cubic and ours fall below V_d, and
 * the refit constrained never to. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "multibounce/multibounce_parts.h"

/* The fraction of the grid row rho = 0 where the cubic < V_d. */
static double row_fraction_rho0(const multibounce_model *m)
{
    const multibounce_cubic c = multibounce_cubic_at(m, 0.0);
    int below = 0;
    for (int i = 1; i <= MULTIBOUNCE_CLAMP_GRID; ++i) {
        double x = (double)i / MULTIBOUNCE_CLAMP_GRID;
        below += multibounce_cubic_eval(&c, x) < x;
    }
    return (double)below / MULTIBOUNCE_CLAMP_GRID;
}

static void where_it_binds(const multibounce_analysis *a, multibounce_clamp *out)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    out->domain_fraction_talk = multibounce_clamp_domain_fraction(&talk, MULTIBOUNCE_CLAMP_GRID);
    out->domain_fraction_ours = multibounce_clamp_domain_fraction(&a->joint[MB_JOINT_LINEAR].model,
                                                                  MULTIBOUNCE_CLAMP_GRID);
    out->domain_fraction_talk_rho0 = row_fraction_rho0(&talk);
    out->pixel_fraction_talk = a->talk_err[1].below;
    out->pixel_fraction_ours = a->joint_err[MB_JOINT_LINEAR][1].below;
}

int multibounce_study_clamp(const multibounce_data *d, const multibounce_analysis *a, multibounce_clamp *out,
                            gt_error *e)
{
    memset(out, 0, sizeof *out);
    where_it_binds(a, out);
    multibounce_constrained_analysis c;
    if (multibounce_analyse_constrained(d, &c, e) != 0)
        return -1;
    memcpy(out->corner, c.fit.corner, sizeof out->corner);
    multibounce_model_to_vector(&c.fit.model, out->coefficients);
    out->rmse_constrained = c.rmse_constrained;
    out->rmse_unconstrained = c.rmse_unconstrained;
    out->heldout_count = c.heldout_count < MULTIBOUNCE_STUDY_SCENES ? c.heldout_count : MULTIBOUNCE_STUDY_SCENES;
    for (int i = 0; i < out->heldout_count; ++i) {
        multibounce_clamp_heldout_row *r = &out->heldout[i];
        snprintf(r->scene, sizeof r->scene, "%s", d->scenes[c.heldout[i].scene]);
        r->rmse_unconstrained = c.heldout[i].rmse_unconstrained;
        r->rmse_constrained = c.heldout[i].rmse_constrained;
    }
    out->heldout_mean_difference = c.mean_difference;
    out->heldout_difference_se = c.difference_se;
    return 0;
}
