/* CryENGINE 3 (Kaplanyan 2010) on the command line: colour precision and the
 * HDR range (stage hdr-precision; studies/hdr_precision.h), colour-grading
 * LUTs (stage color-grading; studies/color_grading.h): two techniques of one
 * talk (the others, best-fit normals and the NDF fit with spherical
 * Gaussians, are in techniques/best_fit_normals/ and techniques/sg_ndf/). */
#include "cli/technique.h"
#include "report/color_grading_section.h"
#include "report/hdr_precision_section.h"
#include "studies/color_grading.h"
#include "studies/hdr_precision.h"

GTLAB_STUDY_STAGE_NO_REQUEST(all_stage_hdr_precision, hdr_precision_result, hdr_precision_study, hdr_precision_section)

GTLAB_STAGE_TECHNIQUE(hdr_precision, "hdr-precision", "gamma vs linear and HDR lower bounds", all_stage_hdr_precision,
                      HDR_PRECISION_DIR);

GTLAB_STUDY_STAGE_NO_REQUEST(all_stage_color_grading, grading_result, color_grading_study, color_grading_section)

GTLAB_STAGE_TECHNIQUE(color_grading, "color-grading", "colour-grading LUTs", all_stage_color_grading, GRADING_DIR);
