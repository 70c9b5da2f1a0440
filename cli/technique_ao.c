/* Ambient occlusion and bent-normal references: the AO stage of `gtlab all`
 * (its references are the inputs of the screen-space techniques' stages). */
#include "cli/technique.h"
#include "studies/ao_references.h"

static const all_stage stages[] = {
    {"ao", "AO references", all_stage_ao_references, AO_REFERENCES_DIR, NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

const technique technique_ao = {.name = "ao", .stages = stages};
