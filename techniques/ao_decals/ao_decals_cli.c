/* The command-line face of INSIDE's analytic AO decals (Gjoel and Svendsen,
 * GDC 2016): the stage ao-decals of `gtlab all` (the study,
 * ao_decals_study.h, and its section). */
#include "ao_decals/ao_decals_section.h"
#include "cli/technique.h"

GTLAB_STUDY_STAGE(all_stage_ao_decals, ao_decals, ao_decals_section)

const technique technique_ao_decals = {
    .name = "ao-decals",
    .stages = ALL_STAGES({"ao-decals", "AO decals (INSIDE)", all_stage_ao_decals, AO_DECALS_DIR, NULL}),
};
