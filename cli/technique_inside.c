/* INSIDE (Gjoel, GDC 2016): AO decals (studies/ao_decals.h); dithering and
 * the bloom refit are techniques/dither/ and techniques/bloom/. */
#include "cli/technique.h"
#include "report/ao_decals_section.h"

GTLAB_STUDY_STAGE(all_stage_ao_decals, ao_decals, ao_decals_section)

const technique technique_inside = {
    .name = "inside",
    .stages = ALL_STAGES({"ao-decals", "AO decals (INSIDE)", all_stage_ao_decals, AO_DECALS_DIR, NULL}),
};
