/* Ray throughput: raw Embree against the reference loops (gtlab bench rays
 * on the command line; its section of `gtlab all`). */
#include "cli/technique.h"

static const all_stage stages[] = {
    {"throughput", "ray throughput", all_stage_ray_throughput, NULL, NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

const technique technique_throughput = {.name = "throughput", .stages = stages};
