/* gtlab bench sphere-light: Karis's GetNoHSquared against Decima's one
 * Newton step, in instructions and in time (studies/sphere_light.h, sphere_cost_study). */
#include <math.h>
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "studies/sphere_light.h"

static const cli_option options[] = {
    CLI_INT("count", "N", 1024, 1L << 28, "configurations per pass"), CLI_INT("repeats", "R", 1, 100, "passes"),
    CLI_END};
static const cli_command command = {
    "bench sphere-light",
    "The cost of GetNoHSquared without (Karis) and with (Decima) the Newton step, as C\n"
    "compiled in this binary (x86-64 scalar SSE, -O3, steps always inlined):\n"
    "  instructions   static count of each function's instructions, from objdump's\n"
    "                 disassembly of this binary (both are straight code but for the\n"
    "                 early-out branch)\n"
    "  time           nanoseconds per call over an array of N random configurations,\n"
    "                 one thread, best of R passes\n"
    "The talk measured +87% GPU cycles for the step; a CPU is not a GPU, so both figures\n"
    "are printed, not compared.",
    options, NULL, NULL};

int bench_sphere_light(int argc, char **argv)
{
    long count = 1L << 22, repeats = 5;
    int status;
    if (cli_options_parse(&command, (void *[]){&count, &repeats}, argc, argv, &status) != 0)
        return status;
    sphere_cost cost;
    sphere_cost_study(count, (int)repeats, &cost);
    if (isnan(cost.ns_karis))
        return cli_failf("bench sphere-light", "out of memory for %ld configurations", count);
    printf("GetNoHSquared, %ld configurations (R inside the light in %.1f%%), best of %ld passes\n", count,
           100.0 * cost.share_early_out, repeats);
    printf("%-24s %14s %14s\n", "", "Karis", "Decima (+1 step)");
    if (cost.instructions_karis > 0 && cost.instructions_decima > 0)
        printf("%-24s %14d %14d   %+.0f%% (calls inside: %d, %d)\n", "x86-64 instructions", cost.instructions_karis,
               cost.instructions_decima,
               100.0 * (cost.instructions_decima - cost.instructions_karis) / cost.instructions_karis, cost.calls_karis,
               cost.calls_decima);
    else
        printf("%-24s %14s %14s   (objdump not found)\n", "x86-64 instructions", "n/a", "n/a");
    printf("%-24s %14.2f %14.2f   %+.0f%%\n", "ns per call", cost.ns_karis, cost.ns_decima,
           100.0 * (cost.ns_decima - cost.ns_karis) / cost.ns_karis);
    printf("the talk: +87%% GPU cycles\n");
    return EXIT_OK;
}
