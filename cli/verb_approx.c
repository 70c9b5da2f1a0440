/* gtlab approx TECHNIQUE: a real-time approximation run on a G-buffer. This
 * file holds only the table of techniques and the dispatch; each technique
 * lives in cli/approx_<technique>.c. */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} approx_technique;

static const approx_technique techniques[] = {
    {"gtao", approx_gtao, "ground-truth AO (Jimenez et al. 2016): cosine-weighted horizons, bent normals"},
    {"hbao", approx_hbao, "horizon-based AO (Bavoil et al. 2008): uniform weighting"},
    {"vo", approx_vo, "volumetric obscurance with 4 samples (Loos and Sloan 2010; CryENGINE 3)"},
};

static void print_help(FILE *out)
{
    fprintf(out, "usage: gtlab approx TECHNIQUE --gbuffer G.exr [options] -o out.exr\n\n"
                 "Runs a real-time technique on a G-buffer EXR (depth.Z, N.*, mask.A and its\n"
                 "camera), the same pixels a reference saw. Techniques:\n");
    for (size_t i = 0; i < sizeof techniques / sizeof techniques[0]; ++i)
        fprintf(out, "  %-6s %s\n", techniques[i].name, techniques[i].summary);
    fprintf(out, "\n'gtlab approx TECHNIQUE --help' lists each technique's options.\n");
}

int verb_approx(int argc, char **argv)
{
    if (argc < 2) {
        print_help(stderr);
        return EXIT_USER_ERROR;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        print_help(stdout);
        return EXIT_OK;
    }
    for (size_t i = 0; i < sizeof techniques / sizeof techniques[0]; ++i)
        if (strcmp(argv[1], techniques[i].name) == 0) {
            cli_reset_getopt();
            return techniques[i].run(argc - 1, argv + 1);
        }
    return cli_failf(argv[1], "unknown technique (see 'gtlab approx --help')");
}
