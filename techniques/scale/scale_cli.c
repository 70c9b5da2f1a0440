/* MPI renders (issue 20): `gtlab bench scale`, measured strong scaling and
 * its projection (scale/scale_bench.h). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "scale/scale_bench.h"

static const cli_option options[] = {CLI_END};
static const cli_command command = {"bench scale", "Times one AO reference and the reduction of its film under this job's ranks\n"
                                    "(alone: one process; `mpirun -n N gtlab bench scale`: N ranks) and projects\n"
                                    "the time on 1, 16 and 256 such nodes.", options, NULL, NULL};

static int bench_scale(int argc, char **argv)
{
    int status;
    if (cli_options_parse(&command, (void *[]){NULL}, argc, argv, &status) != 0)
        return status;
    gt_error e;
    return scale_bench_run(stdout, &e) == 0 ? EXIT_OK : cli_fail(&e);
}

const technique technique_scale = {
    .name = "scale",
    .subcommands = {[VERB_BENCH] = CLI_SUBCOMMANDS({"scale", bench_scale, "MPI strong scaling measured, and projected to 16 and 256 nodes"})},
};
