/* What every `gtlab approx TECHNIQUE` shares on the command line: the options
 * common to every technique, reading the G-buffer (studies/gbuffer_input.h)
 * and writing the result (ao.V, optional bent.*, mask.A copied, header naming
 * the technique and its parameters) atomically. */
#ifndef GTLAB_CLI_APPROX_IO_H
#define GTLAB_CLI_APPROX_IO_H

#include <getopt.h>
#include <stddef.h>

#include "core/image.h"
#include "realtime/screen_space.h"
#include "studies/gbuffer_input.h"

/* getopt_long entries of the common options (end the table with them). */
#define APPROX_COMMON_OPTIONS                                                                                         \
    {"gbuffer", required_argument, 0, 'g'}, {"camera", required_argument, 0, 'c'},                                   \
        {"threads", required_argument, 0, 't'}, {"output", required_argument, 0, 'o'}, {"help", no_argument, 0, 'h'}, \
    {                                                                                                                 \
        0, 0, 0, 0                                                                                                    \
    }
/* "on" / "off" -> 1 / 0; -1 after an error (printed). */
int approx_parse_switch(const char *option, const char *arg, int *out);

/* A technique's command line: its getopt_long table (its own options, then
 * APPROX_COMMON_OPTIONS), its help, its option parser, the text of its
 * parameters for the header, and the computation. */
typedef struct {
    const char *name; /* "hbao" */
    const struct option *options;
    void (*print_help)(void);
    int (*parse_option)(int c, const char *arg, void *params); /* 0, or -1 after an error (printed) */
    void (*settings_text)(const void *params, char *text, size_t size);
    int (*compute)(const ss_gbuffer *g, const void *params, image *out); /* into out, which holds mask.A */
} approx_technique;

/* Parses argv into params (already holding the defaults), then loads the
 * G-buffer, computes and writes the output: returns the exit status. */
int approx_main(const approx_technique *t, void *params, int argc, char **argv);

/* Help lines of the common options. */
extern const char approx_common_help[];
#define APPROX_FRAMES_HELP /* the pattern, denoiser and accumulation options of the horizon techniques */ \
    "  --pattern on|off      the GTAO talk's 4x4 spatio-temporal pattern (default on)\n"                  \
    "  --denoise on|off      the 4x4 bilateral spatial denoiser (default off)\n"                           \
    "  --frames N            frames accumulated (static camera; default 1)\n"

#endif
