/* The command line of `gtlab approx` techniques; see approx_io.h. */
#include "cli/approx_io.h"

#include <getopt.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "core/exr_io.h"
#include "core/threads.h"

const char approx_common_help[] =
    "  --gbuffer G.exr       input: an EXR with depth.Z, N.X, N.Y, N.Z and mask.A (from\n"
    "                        'gtlab render gbuffer' or any reference render)\n"
    "  --camera cam.json     its camera (default: the EXR's gtlab.camera header, else\n"
    "                        G.camera.json beside it)\n"
    "  --threads T           worker threads (default: all cores); the output does not\n"
    "                        depend on it\n"
    "  -o, --output F.exr    output EXR: ao.V (and bent.X/Y/Z where the technique has\n"
    "                        them), mask.A, the header naming technique and parameters\n"
    "  -h, --help\n";

/* The options every technique takes. */
typedef struct {
    const char *gbuffer, *camera, *output;
    long threads; /* 0: all cores */
} approx_common;

/* 1 if c is a common option (stored), 0 if not, -1 after an error (printed). */
static int common_option(int c, const char *arg, approx_common *common)
{
    switch (c) {
    case 'g': common->gbuffer = arg; return 1;
    case 'c': common->camera = arg; return 1;
    case 'o': common->output = arg; return 1;
    case 't': return cli_parse_int("--threads", arg, 1, 1024, &common->threads) == 0 ? 1 : -1;
    default: return 0;
    }
}

int approx_parse_switch(const char *option, const char *arg, int *out)
{
    if (strcmp(arg, "on") == 0 || strcmp(arg, "off") == 0) {
        *out = arg[1] == 'n';
        return 0;
    }
    return cli_failf(option, "'%s' is neither on nor off", arg), -1;
}

/* Loads, computes, writes: returns the exit status. */
static int run(const approx_technique *t, const approx_common *c, const void *params)
{
    char settings[640];
    t->settings_text(params, settings, sizeof settings);
    gt_error e;
    approx_input in;
    if (approx_load(c->gbuffer, c->camera, &in, &e) != 0)
        return cli_fail(&e);
    if (c->threads > 0)
        threads_set((int)c->threads);
    image out = {0};
    int status = EXIT_OK;
    if (approx_output_init(&in, t->name, settings, &out) != 0 || t->compute(&in.g, params, &out) != 0) {
        fprintf(stderr, "gtlab: %s: out of memory\n", t->name);
        status = EXIT_INTERNAL_ERROR;
    } else if (exr_write(c->output, &out, &e) != 0) {
        status = cli_fail(&e);
    }
    image_free(&out);
    approx_input_free(&in);
    return status;
}

int approx_main(const approx_technique *t, void *params, int argc, char **argv)
{
    approx_common common = {0};
    int c;
    while ((c = getopt_long(argc, argv, "o:h", t->options, NULL)) != -1) {
        if (c == 'h')
            return t->print_help(), EXIT_OK;
        int handled = common_option(c, optarg, &common);
        if (handled < 0 || (handled == 0 && t->parse_option(c, optarg, params) != 0))
            return EXIT_USER_ERROR;
    }
    if (optind < argc)
        return cli_failf(argv[optind], "unexpected argument (see 'gtlab approx %s --help')", t->name);
    if (!common.gbuffer)
        return cli_failf(t->name, "no --gbuffer given (see 'gtlab approx %s --help')", t->name);
    if (!common.output)
        return cli_failf(t->name, "no output given: -o out.exr");
    return run(t, &common, params);
}
