/* The command-line face of colour-grading LUTs: the stage color-grading of
 * `gtlab all` (the study, color_grading/color_grading_study.h, and its
 * section). */
#include "cli/technique.h"
#include "color_grading/color_grading_section.h"
#include "color_grading/color_grading_study.h"

GTLAB_STUDY_STAGE_NO_REQUEST(all_stage_color_grading, grading_result, color_grading_study, color_grading_section)

GTLAB_STAGE_TECHNIQUE(color_grading, "color-grading", "colour-grading LUTs", all_stage_color_grading, GRADING_DIR);
