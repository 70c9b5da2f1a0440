/* gtlab fit multibounce: the GTAO multi-bounce cubic (Jimenez et al. 2016,
 * "Multiple Bounces" to "Shader Code") refitted to multi-bounce references;
 * the data studies/multibounce_fit_input.h, the fits fitters/fit_multibounce.h,
 * the formula realtime/multibounce.h. */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "core/atomic_file.h"
#include "fitters/fit_multibounce.h"
#include "studies/multibounce_fit_input.h"

enum { MAX_FILES = 256 };

static const cli_option options[] = {
    CLI_CUSTOM("data", "F ...", cli_list_add, "reference EXRs (the option may repeat; further file names\n"
               "after it are data too); all rendered with the same --bounces"),
    CLI_OUTPUT("F", 0, "the JSON: coefficients, standard errors, covariance, RMSE and\n"
               "max error on the data, the talk's on the same data, LOO\n"
               "table, data used (files, scenes, albedos, counts, weights)"),
    CLI_STRING("header", "F.h", "C header with the fitted functions (default: F without .json, .h)"),
    CLI_STRING("hlsl", "F.hlsl", "HLSL GTAOMultiBounce with the new coefficients (default: .hlsl)"),
    CLI_STRING("glsl", "F.glsl", "the same in GLSL (default: .glsl)"), CLI_END};
static const cli_command command = {
    "fit multibounce",
    "Fits V'_d = max(V_d, ((a V_d + b) V_d + c) V_d) (GTAOMultiBounce, Jimenez et al. 2016)\n"
    "to references made by 'gtlab render multibounce --albedo 0.1,0.2,...' (grey albedos;\n"
    "each surface pixel, mask.A = 1, gives one sample (V_d = ao.V, V'_d, albedo) per albedo):\n"
    "  per albedo      the cubic's a, b, c\n"
    "  joint linear    a = a0 + a1 albedo, b, c likewise, fitted to all samples at once\n"
    "  joint quadratic a, b, c quadratic in the albedo (3+ albedos), preferred only if\n"
    "                  its leave-one-scene-out error is lower\n"
    "Every scene and every albedo counts equally, whatever its pixel count. With 2+\n"
    "scenes (the files' gtlab.scene) each scene is held out in turn: the model fitted\n"
    "on the others is scored on it. The talk's published coefficients are scored on\n"
    "the same data. Fits run through Ceres; standard errors from its covariance.",
    options, "[B.exr ...]",
    "example: gtlab render multibounce --scene builtin:corner --albedo 0.1,0.2,0.3,0.4,0.5,0.7,0.9 -o c.exr\n"
    "         gtlab fit multibounce --data c.exr m.exr -o fit.json\n"
    "exit status: 0 success, 1 bad input, 2 internal error"};

/* F without a trailing ".json", with `extension` appended. */
static void sibling_path(const char *json, const char *extension, char *out, size_t size)
{
    size_t n = strlen(json);
    if (n > 5 && strcmp(json + n - 5, ".json") == 0)
        n -= 5;
    snprintf(out, size, "%.*s%s", (int)n, json, extension);
}

static void print_fit(const char *title, const multibounce_fit *f, const multibounce_errors *err)
{
    printf("%s (RMSE %.4g, max |error| %.4g):\n ", title, err->rmse, err->max_abs);
    for (int i = 0; i < f->parameter_count; ++i) {
        char name[8];
        multibounce_fit_parameter_name(f, i, name, sizeof name);
        printf(" %s = %.5f (±%.5f)", name, f->params[i], f->standard_errors[i]);
    }
    printf("\n");
}

static void print_summary(const multibounce_data *d, const multibounce_analysis *a)
{
    printf("%zu samples: %d scenes, %d albedos, --bounces %s\n", d->count, d->scene_count, d->albedo_count,
           d->bounces);
    for (int j = 0; j < MB_JOINT_COUNT; ++j)
        if (a->has[j])
            print_fit(multibounce_joint_names[j], &a->joint[j], &a->joint_err[j][1]);
    printf("talk's coefficients on the same data: RMSE %.4g, max |error| %.4g\n", a->talk_err[1].rmse,
           a->talk_err[1].max_abs);
    if (a->heldout_count) {
        printf("leave-one-scene-out mean RMSE:");
        for (int j = 0; j < MB_JOINT_COUNT; ++j)
            if (a->has[j])
                printf(" %s %.4g,", multibounce_joint_names[j], a->heldout_mean[j]);
        printf(" talk %.4g; chosen: %s\n", a->heldout_mean_talk, multibounce_joint_names[a->chosen]);
    }
}

/* The command line as one string, for the outputs' provenance. */
static void command_text(int argc, char **argv, char *out, size_t size)
{
    size_t used = (size_t)snprintf(out, size, "gtlab fit");
    for (int i = 0; i < argc && used < size; ++i)
        used += (size_t)snprintf(out + used, size - used, " %s", argv[i]);
}

int fit_multibounce(int argc, char **argv)
{
    const char *files[MAX_FILES], *output = NULL, *header = NULL, *hlsl = NULL, *glsl = NULL;
    cli_list data = {files, 0, MAX_FILES, "--data"};
    cli_arguments more;
    char command_line[4096];
    command_text(argc, argv, command_line, sizeof command_line); /* before getopt permutes argv */
    int status;
    if (cli_options_parse(&command, (void *[]){&data, &output, &header, &hlsl, &glsl, &more}, argc, argv, &status) != 0)
        return status;
    if (more.count > 0 && data.count == 0)
        return cli_failf("fit multibounce", "unexpected argument '%s' (data files follow --data)", more.values[0]);
    for (int i = 0; i < more.count; ++i)
        if (cli_list_add(&data, more.values[i]) != 0)
            return EXIT_USER_ERROR;
    if (data.count == 0)
        return cli_failf("--data", "no reference files given (see 'gtlab fit multibounce --help')");
    if (!output)
        return cli_failf("-o", "an output file is required (fit.json)");
    char header_path[4096], hlsl_path[4096], glsl_path[4096];
    sibling_path(output, ".h", header_path, sizeof header_path);
    sibling_path(output, ".hlsl", hlsl_path, sizeof hlsl_path);
    sibling_path(output, ".glsl", glsl_path, sizeof glsl_path);
    if (!header)
        header = header_path;
    if (!hlsl)
        hlsl = hlsl_path;
    if (!glsl)
        glsl = glsl_path;
    gt_error e;
    if (atomic_file_check_writable(output, &e) != 0 || atomic_file_check_writable(header, &e) != 0 ||
        atomic_file_check_writable(hlsl, &e) != 0 || atomic_file_check_writable(glsl, &e) != 0)
        return cli_fail(&e);
    multibounce_data d;
    multibounce_data_init(&d);
    multibounce_analysis *a = malloc(sizeof *a);
    status = EXIT_OK;
    if (!a)
        status = cli_failf("fit multibounce", "out of memory");
    else if (multibounce_fit_input_load(files, data.count, &d, &e) != 0 || multibounce_analyse(&d, a, &e) != 0 ||
             multibounce_write_outputs(&d, a, command_line, output, header, hlsl, glsl, &e) != 0)
        status = cli_fail(&e);
    else
        print_summary(&d, a);
    free(a);
    multibounce_data_free(&d);
    return status;
}
