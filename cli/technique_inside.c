/* INSIDE (Gjoel, GDC 2016): the bloom downsample's 13 -> 9 tap refit
 * (studies/bloom.h), AO decals (studies/ao_decals.h); dithering is
 * techniques/dither/. */
#include "cli/technique.h"
#include "report/ao_decals_section.h"
#include "report/bloom_section.h"

GTLAB_STUDY_STAGE(all_stage_bloom, bloom, bloom_section)

GTLAB_STUDY_STAGE(all_stage_ao_decals, ao_decals, ao_decals_section)

const technique technique_inside = {
    .name = "inside",
    .stages = ALL_STAGES(
        {"bloom", "bloom 13 -> 9 tap refit (INSIDE)", all_stage_bloom, BLOOM_DIR, NULL},
        {"ao-decals", "AO decals (INSIDE)", all_stage_ao_decals, AO_DECALS_DIR, NULL}),
};
