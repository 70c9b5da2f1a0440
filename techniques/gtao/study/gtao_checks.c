#include "gtao/gtao_checks.h"

int gtao_checks_study(const study_context *ctx, const gtao_shortcuts_request *rq, gtao_checks_result *out,
                      gt_error *e)
{
    if (gtao_fast_math_study(ctx, rq, &out->fast_math, e) != 0 || gtao_baselines_study(ctx, rq, &out->baselines, e) != 0 ||
        gtao_bent_normals_study(ctx, rq, &out->bent, e) != 0 ||
        gtao_thickness_study(ctx, rq, &out->thickness, e) != 0 ||
        gtao_distance_fade_study(ctx, rq, &out->fade, e) != 0 ||
        vbao_study(ctx, rq, gtao_thickness_values[out->thickness.best], &out->vbao, e) != 0)
        return -1;
    return 0;
}
