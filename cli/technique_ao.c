/* Ambient occlusion and bent-normal references: the AO stage of `gtlab all`
 * (its references are the inputs of the screen-space techniques' stages). */
#include "cli/cli.h"
#include "cli/technique.h"
#include "report/ao_section.h"
#include "studies/ao_references.h"

GTLAB_STUDY_STAGE(all_stage_ao_references, ao_references, ao_references_section)

const technique technique_ao = {
    .name = "ao",
    .subcommands = {[VERB_BENCH] = CLI_SUBCOMMANDS(
        {"convergence", bench_convergence, "AO time to RMSE 0.01, plain against the height-field control variate"})},
    .stages = ALL_STAGES({"ao", "AO references", all_stage_ao_references, AO_REFERENCES_DIR, NULL}),
};
