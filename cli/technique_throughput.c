/* Ray throughput: raw Embree against the reference loops (gtlab bench rays
 * on the command line; its section of `gtlab all`). */
#include "cli/technique.h"
#include "report/ray_throughput_section.h"

static int all_stage_ray_throughput(report_context *ctx, gt_error *e)
{
    ray_throughput_result r;
    return ray_throughput_study(&ctx->study, &r, e) != 0 ? -1 : ray_throughput_section(ctx, &r, e);
}

static const all_stage stages[] = {
    {"throughput", "ray throughput", all_stage_ray_throughput, NULL, NULL},
    {NULL, NULL, NULL, NULL, NULL}};

const technique technique_throughput = {.name = "throughput", .stages = stages};
