/* The command-line face of colour precision and the HDR range: the stage
 * hdr-precision of `gtlab all` (the study, hdr_precision/hdr_precision_study.h,
 * and its section). */
#include "cli/technique.h"
#include "hdr_precision/hdr_precision_section.h"
#include "hdr_precision/hdr_precision_study.h"

GTLAB_STUDY_STAGE_NO_REQUEST(all_stage_hdr_precision, hdr_precision_result, hdr_precision_study, hdr_precision_section)

GTLAB_STAGE_TECHNIQUE(hdr_precision, "hdr-precision", "gamma vs linear and HDR lower bounds", all_stage_hdr_precision,
                      HDR_PRECISION_DIR);
