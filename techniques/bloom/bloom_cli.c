/* The command-line face of the bloom downsample's 13 -> 9 tap refit (INSIDE,
 * Gjoel and Svendsen, GDC 2016): the stage bloom of `gtlab all` (the study,
 * bloom_study.h, and its section). */
#include "bloom/bloom_section.h"
#include "cli/technique.h"

GTLAB_STUDY_STAGE(all_stage_bloom, bloom, bloom_section)

const technique technique_bloom = {
    .name = "bloom",
    .stages = ALL_STAGES({"bloom", "bloom 13 -> 9 tap refit (INSIDE)", all_stage_bloom, BLOOM_DIR, NULL}),
};
