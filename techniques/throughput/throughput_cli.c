/* Ray throughput: raw Embree against the reference loops (gtlab bench rays
 * on the command line; its section of `gtlab all`). */
#include "cli/technique.h"
#include "throughput/ray_throughput_section.h"

GTLAB_STUDY_STAGE_NO_REQUEST(all_stage_ray_throughput, ray_throughput_result, ray_throughput_study,
                             ray_throughput_section)
GTLAB_STAGE_TECHNIQUE(throughput, "throughput", "ray throughput", all_stage_ray_throughput, NULL);
