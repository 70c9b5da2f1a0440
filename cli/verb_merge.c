/* gtlab merge: combine partial renders of disjoint sample blocks exactly. */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "core/files/atomic_file.h"
#include "core/files/exr_io.h"
#include "cli/render_quantities.h"
#include "raytracer/reference_merge.h"

static const cli_option options[] = {
    CLI_OUTPUT("F.exr", 0, "merged render"),
    CLI_STRING("expect-blocks", "S:K+N", "the parts of one plan ('gtlab plan'): refuse inputs with other\n"
               "samples and a merge that leaves some of these out"), CLI_END};
static const cli_command command = {
    "merge",
    "Combines reference renders of the same quantity, scene, camera and settings\n"
    "whose samples are disjoint (other --sample-offset blocks of one seed, or other\n"
    "seeds) into the render over all of their samples. The sums are exact, so the\n"
    "result is bit-identical to a single render over the same samples. Inputs that\n"
    "overlap, or belong to different renders, are refused.",
    options, "A.exr B.exr [C.exr ...]", NULL};

int verb_merge(int argc, char **argv)
{
    const char *output = NULL, *planned = NULL;
    cli_arguments files;
    int status;
    if (cli_options_parse(&command, (void *[]){&output, &planned, &files}, argc, argv, &status) != 0)
        return status;
    int count = files.count;
    if (count < 2)
        return cli_failf("merge", "give at least two renders to merge");
    if (!output)
        return cli_failf("merge", "-o/--output is required");
    gt_error e;
    if (atomic_file_check_writable(output, &e) != 0)
        return cli_fail(&e);
    image *inputs = calloc((size_t)count, sizeof *inputs);
    if (!inputs)
        return cli_failf("merge", "out of memory");
    int loaded = 0;
    for (; loaded < count; ++loaded)
        if (exr_read(files.values[loaded], &inputs[loaded], &e) != 0) {
            status = cli_fail(&e);
            break;
        }
    image merged;
    if (status == EXIT_OK) {
        if (reference_merge_planned(render_quantities(), inputs, (const char *const *)files.values, count, planned, &merged, &e) != 0 ||
            exr_write(output, &merged, &e) != 0)
            status = cli_fail(&e);
        image_free(&merged);
    }
    for (int i = 0; i < loaded; ++i)
        image_free(&inputs[i]);
    free(inputs);
    return status;
}
