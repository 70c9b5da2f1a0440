/* What every `gtlab approx TECHNIQUE` shares on the command line: the options
 * common to every technique, reading the G-buffer (project/gbuffer_input.h)
 * and writing the result (ao.V, optional bent.*, mask.A copied, header naming
 * the technique and its parameters) atomically. */
#ifndef GTLAB_CLI_APPROX_IO_H
#define GTLAB_CLI_APPROX_IO_H

#include <stddef.h>

#include "cli/cli_options.h"
#include "core/image.h"
#include "realtime/screen_space.h"
#include "project/gbuffer_input.h"

/* A technique's command line: its options (ending CLI_END; the common ones
 * --gbuffer, --camera, --threads, -o follow), the text of its parameters
 * for the header, and the computation. */
typedef struct {
    const char *name; /* "hbao" */
    const char *description;
    const cli_option *options;
    void (*settings_text)(const void *params, char *text, size_t size);
    int (*compute)(const ss_gbuffer *g, const void *params, image *out); /* into out, which holds mask.A */
} approx_technique;

/* Parses argv into params (already holding the defaults) through dest, the
 * destinations of t->options, then loads the G-buffer, computes and writes
 * the output: returns the exit status. */
int approx_main(const approx_technique *t, void *params, void *const *dest, int argc, char **argv);

/* The pattern, denoiser and accumulation options of the horizon techniques. */
#define APPROX_FRAME_OPTIONS                                                 \
    CLI_SWITCH("pattern", "the GTAO talk's 4x4 spatio-temporal pattern"),    \
        CLI_SWITCH("denoise", "the 4x4 bilateral spatial denoiser"),         \
        CLI_INT32("frames", "N", 1, 100000, "frames accumulated (static camera)")

#endif
