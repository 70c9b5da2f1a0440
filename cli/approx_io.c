/* The command line of `gtlab approx` techniques; see approx_io.h. */
#include "cli/approx_io.h"

#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "core/files/exr_io.h"
#include "core/threads.h"

enum { MAX_TECHNIQUE_OPTIONS = 24 };

static const cli_option common_options[] = {
    CLI_STRING("gbuffer", "G.exr", "input: an EXR with depth.Z, N.X, N.Y, N.Z and mask.A (from\n"
               "'gtlab render gbuffer' or any reference render)"),
    CLI_STRING("camera", "cam.json", "its camera (default: the EXR's gtlab.camera header, else\nG.camera.json beside it)"),
    CLI_THREADS,
    CLI_OUTPUT("F.exr", 0, "output EXR: ao.V (and bent.X/Y/Z where the technique has\n"
               "them), mask.A, the header naming technique and parameters"),
    CLI_END};
enum { COMMON_OPTIONS = sizeof common_options / sizeof common_options[0] };

/* The options every technique takes. */
typedef struct {
    const char *gbuffer, *camera, *output;
    long threads; /* 0: all cores */
} approx_common;

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

int approx_main(const approx_technique *t, void *params, void *const *dest, int argc, char **argv)
{
    cli_option options[MAX_TECHNIQUE_OPTIONS + COMMON_OPTIONS];
    void *dests[MAX_TECHNIQUE_OPTIONS + COMMON_OPTIONS];
    approx_common common = {0};
    int n = 0, status;
    for (; t->options[n].kind != CLI_KIND_END && n < MAX_TECHNIQUE_OPTIONS; ++n)
        options[n] = t->options[n], dests[n] = dest[n];
    memcpy(options + n, common_options, sizeof common_options);
    memcpy(dests + n, (void *[]){&common.gbuffer, &common.camera, &common.threads, &common.output}, 4 * sizeof(void *));
    char name[64];
    snprintf(name, sizeof name, "approx %s", t->name);
    const cli_command command = {name, t->description, options, NULL, NULL};
    if (cli_options_parse(&command, dests, argc, argv, &status) != 0)
        return status;
    if (!common.gbuffer)
        return cli_failf(t->name, "no --gbuffer given (see 'gtlab approx %s --help')", t->name);
    if (!common.output)
        return cli_failf(t->name, "no output given: -o out.exr");
    return run(t, &common, params);
}
