/* CryENGINE 3 (Kaplanyan 2010) on the command line: colour precision and the
 * HDR range (stage hdr-precision; studies/hdr_precision.h), the one technique
 * of the talk still here (the others are in techniques/best_fit_normals/,
 * techniques/color_grading/ and techniques/sg_ndf/). */
#include "cli/technique.h"
#include "report/hdr_precision_section.h"
#include "studies/hdr_precision.h"

GTLAB_STUDY_STAGE_NO_REQUEST(all_stage_hdr_precision, hdr_precision_result, hdr_precision_study, hdr_precision_section)

GTLAB_STAGE_TECHNIQUE(hdr_precision, "hdr-precision", "gamma vs linear and HDR lower bounds", all_stage_hdr_precision,
                      HDR_PRECISION_DIR);
