/* gtlab approx TECHNIQUE: a real-time approximation on a G-buffer. A dispatcher: each
 * technique lives in cli/approx_<name>.c. */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} approx_entry;

static const approx_entry techniques[] = {
    {"specular-occlusion", approx_specular_occlusion, "GTSO and the other specular-occlusion variants from AO + bent normal"},
};

static void print_help(FILE *out)
{
    fprintf(out, "usage: gtlab approx TECHNIQUE --gbuffer g.exr [options] -o out.exr     (gtlab approx TECHNIQUE --help for each)\n\ntechniques:\n");
    for (size_t i = 0; i < sizeof techniques / sizeof techniques[0]; ++i)
        fprintf(out, "  %-20s %s\n", techniques[i].name, techniques[i].summary);
}

int verb_approx(int argc, char **argv)
{
    if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        print_help(argc < 2 ? stderr : stdout);
        return argc < 2 ? EXIT_USER_ERROR : EXIT_OK;
    }
    for (size_t i = 0; i < sizeof techniques / sizeof techniques[0]; ++i)
        if (strcmp(argv[1], techniques[i].name) == 0) {
            cli_reset_getopt();
            return techniques[i].run(argc - 1, argv + 1);
        }
    return cli_failf("approx", "unknown technique '%s' (see 'gtlab approx --help')", argv[1]);
}
