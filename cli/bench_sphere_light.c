/* gtlab bench sphere-light: Karis's GetNoHSquared against Decima's one
 * Newton step, in instructions and in time (cli/bench_sphere_light.h). */
#define _GNU_SOURCE
#include "cli/bench_sphere_light.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"
#include "core/progress.h"
#include "core/sobol.h"
#include "realtime/sphere_light.h"

typedef float (*noh_fn)(float, float, float, float);

/* Counts the instructions (and calls) of `symbol` in the running binary. */
static void count_instructions(const char *symbol, int *instructions, int *calls)
{
    char command[512];
    snprintf(command, sizeof command, "objdump -d --no-show-raw-insn --disassemble=%s /proc/%ld/exe 2>/dev/null",
             symbol, (long)getpid());
    *instructions = -1, *calls = 0;
    FILE *p = popen(command, "r");
    if (!p)
        return;
    char line[512];
    int n = 0;
    while (fgets(line, sizeof line, p)) {
        /* Instruction lines: "  401a2b:\tmnemonic operands". */
        char *colon = strchr(line, ':');
        if (line[0] != ' ' || !colon || colon[1] != '\t')
            continue;
        ++n;
        *calls += strstr(colon, "call") != NULL;
    }
    if (pclose(p) == 0 && n > 0)
        *instructions = n;
}

typedef struct {
    float radius_tan, n_dot_l, n_dot_v, v_dot_l;
} noh_input;

/* Configurations as in `gtlab check sphere-noh`, drawn at random. */
static void make_inputs(noh_input *in, long count)
{
    for (long i = 0; i < count; ++i) {
        double u[4];
        for (int k = 0; k < 4; ++k)
            u[k] = hash_combine(hash_combine(0xbe4c, (uint32_t)i), (uint32_t)k) * 0x1p-32;
        double n_dot_v = 0.02 + 0.98 * u[0], cos_l = u[1], phi = M_PI * u[2];
        double sin_v = sqrt(1.0 - n_dot_v * n_dot_v), sin_l = sqrt(1.0 - cos_l * cos_l);
        in[i].radius_tan = (float)pow(10.0, -3.0 + 3.0 * u[3]);
        in[i].n_dot_l = (float)cos_l, in[i].n_dot_v = (float)n_dot_v;
        in[i].v_dot_l = (float)(sin_v * sin_l * cos(phi) + n_dot_v * cos_l);
    }
}

static double time_function(noh_fn f, const noh_input *in, long count, int repeats, volatile float *sink)
{
    double best = INFINITY;
    for (int r = 0; r < repeats; ++r) {
        double t0 = seconds_now();
        float sum = 0.0f;
        for (long i = 0; i < count; ++i)
            sum += f(in[i].radius_tan, in[i].n_dot_l, in[i].n_dot_v, in[i].v_dot_l);
        best = fmin(best, seconds_now() - t0);
        *sink = sum;
    }
    return 1e9 * best / count;
}

void sphere_cost_measure(long count, int repeats, sphere_cost *out)
{
    const noh_fn fns[2] = {sphere_noh_squared_karis, sphere_noh_squared_decima};
    const char *names[2] = {"sphere_noh_squared_karis", "sphere_noh_squared_decima"};
    noh_input *in = malloc((size_t)count * sizeof *in);
    volatile float sink = 0.0f;
    out->count = count;
    out->share_early_out = 0.0;
    for (int f = 0; f < 2; ++f) {
        count_instructions(names[f], &out->instructions[f], &out->calls[f]);
        out->ns_per_call[f] = NAN;
    }
    if (!in)
        return;
    make_inputs(in, count);
    long early = 0;
    for (long i = 0; i < count; ++i)
        early += 2.0f * in[i].n_dot_l * in[i].n_dot_v - in[i].v_dot_l >= 1.0f / sqrtf(1.0f + in[i].radius_tan * in[i].radius_tan);
    out->share_early_out = (double)early / count;
    for (int f = 0; f < 2; ++f)
        out->ns_per_call[f] = time_function(fns[f], in, count, repeats, &sink);
    free(in);
}

static void print_help(void)
{
    printf("usage: gtlab bench sphere-light [--count N] [--repeats R]\n"
           "\n"
           "The cost of GetNoHSquared without (Karis) and with (Decima) the Newton step, as C\n"
           "compiled in this binary (x86-64 scalar SSE, -O3, steps always inlined):\n"
           "  instructions   static count of each function's instructions, from objdump's\n"
           "                 disassembly of this binary (both are straight code but for the\n"
           "                 early-out branch)\n"
           "  time           nanoseconds per call over an array of N random configurations,\n"
           "                 one thread, best of R passes\n"
           "The talk measured +87%% GPU cycles for the step; a CPU is not a GPU, so both figures\n"
           "are printed, not compared.\n"
           "\n"
           "  --count N     configurations per pass (default 4194304)\n"
           "  --repeats R   passes (default 5)\n");
}

int bench_sphere_light(int argc, char **argv)
{
    static const struct option longs[] = {{"count", required_argument, 0, 'n'},
                                          {"repeats", required_argument, 0, 'r'},
                                          {"help", no_argument, 0, 'h'},
                                          {0, 0, 0, 0}};
    long count = 1L << 22, repeats = 5;
    int c;
    while ((c = getopt_long(argc, argv, "h", longs, NULL)) != -1) {
        switch (c) {
        case 'n': if (cli_parse_int("--count", optarg, 1024, 1L << 28, &count)) return EXIT_USER_ERROR; break;
        case 'r': if (cli_parse_int("--repeats", optarg, 1, 100, &repeats)) return EXIT_USER_ERROR; break;
        case 'h': print_help(); return EXIT_OK;
        default: return cli_usage_error("bench sphere-light");
        }
    }
    if (optind < argc)
        return cli_failf("bench sphere-light", "unexpected argument '%s'", argv[optind]);
    sphere_cost cost;
    sphere_cost_measure(count, (int)repeats, &cost);
    if (isnan(cost.ns_per_call[0]))
        return cli_failf("bench sphere-light", "out of memory for %ld configurations", count);
    printf("GetNoHSquared, %ld configurations (R inside the light in %.1f%%), best of %ld passes\n", count,
           100.0 * cost.share_early_out, repeats);
    printf("%-24s %14s %14s\n", "", "Karis", "Decima (+1 step)");
    if (cost.instructions[0] > 0 && cost.instructions[1] > 0)
        printf("%-24s %14d %14d   %+.0f%% (calls inside: %d, %d)\n", "x86-64 instructions", cost.instructions[0],
               cost.instructions[1], 100.0 * (cost.instructions[1] - cost.instructions[0]) / cost.instructions[0],
               cost.calls[0], cost.calls[1]);
    else
        printf("%-24s %14s %14s   (objdump not found)\n", "x86-64 instructions", "n/a", "n/a");
    printf("%-24s %14.2f %14.2f   %+.0f%%\n", "ns per call", cost.ns_per_call[0], cost.ns_per_call[1],
           100.0 * (cost.ns_per_call[1] - cost.ns_per_call[0]) / cost.ns_per_call[0]);
    printf("the talk: +87%% GPU cycles\n");
    return EXIT_OK;
}
