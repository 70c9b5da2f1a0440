/* gtlab lut NAME: a lookup table in every output format. A dispatcher: each
 * table lives in cli/lut_<name>.c. */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} lut_entry;

static const lut_entry luts[] = {
    {"specular-occlusion", lut_specular_occlusion, "GTSO cone/lobe V_s(a_v, beta, r): EXR, 8-bit PNG, C header"},
};

static void print_help(FILE *out)
{
    fprintf(out, "usage: gtlab lut NAME [options] -o DIR     (gtlab lut NAME --help for each)\n\ntables:\n");
    for (size_t i = 0; i < sizeof luts / sizeof luts[0]; ++i)
        fprintf(out, "  %-20s %s\n", luts[i].name, luts[i].summary);
}

int verb_lut(int argc, char **argv)
{
    if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        print_help(argc < 2 ? stderr : stdout);
        return argc < 2 ? EXIT_USER_ERROR : EXIT_OK;
    }
    for (size_t i = 0; i < sizeof luts / sizeof luts[0]; ++i)
        if (strcmp(argv[1], luts[i].name) == 0) {
            cli_reset_getopt();
            return luts[i].run(argc - 1, argv + 1);
        }
    return cli_failf("lut", "unknown table '%s' (see 'gtlab lut --help')", argv[1]);
}
