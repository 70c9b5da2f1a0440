/* gtlab merge: combine partial renders of disjoint sample blocks exactly. */
#define _GNU_SOURCE
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "core/atomic_file.h"
#include "core/exr_io.h"
#include "raytracer/reference_merge.h"

static void print_help(void)
{
    printf("usage: gtlab merge A.exr B.exr [C.exr ...] -o OUT.exr\n"
           "\n"
           "Combines reference renders of the same quantity, scene, camera and settings\n"
           "whose samples are disjoint (other --sample-offset blocks of one seed, or other\n"
           "seeds) into the render over all of their samples. The sums are exact, so the\n"
           "result is bit-identical to a single render over the same samples. Inputs that\n"
           "overlap, or belong to different renders, are refused.\n"
           "\n"
           "  -o, --output F.exr   merged render\n"
           "  -h, --help\n");
}

int verb_merge(int argc, char **argv)
{
    static const struct option longs[] = {
        {"output", required_argument, 0, 'o'}, {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    const char *output = NULL;
    int c;
    while ((c = getopt_long(argc, argv, "o:h", longs, NULL)) != -1) {
        if (c == 'o')
            output = optarg;
        else if (c == 'h')
            return print_help(), EXIT_OK;
        else
            return cli_usage_error("merge");
    }
    int count = argc - optind;
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
    int status = EXIT_OK, loaded = 0;
    for (; loaded < count; ++loaded)
        if (exr_read(argv[optind + loaded], &inputs[loaded], &e) != 0) {
            status = cli_fail(&e);
            break;
        }
    image merged;
    if (status == EXIT_OK) {
        if (reference_merge(inputs, (const char *const *)&argv[optind], count, &merged, &e) != 0 ||
            exr_write(output, &merged, &e) != 0)
            status = cli_fail(&e);
        image_free(&merged);
    }
    for (int i = 0; i < loaded; ++i)
        image_free(&inputs[i]);
    free(inputs);
    return status;
}
