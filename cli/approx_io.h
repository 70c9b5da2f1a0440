/* What every `gtlab approx TECHNIQUE` shares: reading the G-buffer EXR and
 * its camera, the options common to every technique, and writing the result
 * (ao.V, optional bent.*, mask.A copied, header naming the technique and its
 * parameters) atomically. */
#ifndef GTLAB_CLI_APPROX_IO_H
#define GTLAB_CLI_APPROX_IO_H

#include <getopt.h>
#include <stddef.h>

#include "core/error.h"
#include "core/image.h"
#include "realtime/screen_space.h"
#include "scene/camera.h"

typedef struct {
    image img;
    ss_gbuffer g;
    camera cam;
} approx_input;

/* The camera of a G-buffer as real-time code sees it. */
ss_camera approx_ss_camera(const camera *cam);

/* Reads `path` (an EXR with depth.Z, N.X/Y/Z and mask.A) and its camera:
 * camera_path if given, else the header's gtlab.camera, else the sidecar
 * <path>.camera.json. Returns 0, or -1 with e naming the file at fault. */
int approx_load(const char *path, const char *camera_path, approx_input *in, gt_error *e);
void approx_input_free(approx_input *in);

/* A fresh output image of the input's size holding mask.A and the header
 * (gtlab.quantity = "approx", gtlab.technique, gtlab.settings, and the
 * input's gtlab.camera / gtlab.scene). Returns 0 or -1 when out of memory. */
int approx_output_init(const approx_input *in, const char *technique, const char *settings, image *out);

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

#endif
