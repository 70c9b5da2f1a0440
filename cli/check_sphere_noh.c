/* gtlab check sphere-noh: how close Karis's point and de Carpentier's
 * Newton step (Decima, SIGGRAPH 2017) come to the maximum of (N.H)^2 over a
 * spherical light, against a brute-force search (studies/sphere_light.h). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "report/sphere_noh_figures.h"
#include "studies/sphere_light.h"

static const cli_option options[] = {
    CLI_OUTPUT("DIR", 0, "output folder"),
    CLI_INT("steps", "N", 2, 64, "grid points per dimension (default 16: 65536 configurations)"),
    CLI_INT("rim-steps", "K", 16, 65536, "brute-force angles on the rim before refinement"), CLI_END};
static const cli_command command = {
    "check sphere-noh",
    "How close GetNoHSquared (Decima, SIGGRAPH 2017) comes to the largest (N.H)^2 over a\n"
    "spherical light: for every configuration of a grid over n.v, the light's elevation\n"
    "and azimuth and its angular size (tan(sigma) from 0.001 to 1), the shortfall below\n"
    "the brute-force maximum over the rim of Karis's point (0 Newton steps), the talk's\n"
    "one Newton step, two steps, and one step guarded (taken only where f''(0) < 0, i.e.\n"
    "where it heads for a maximum; not in the talk). Prints the mean, 99th percentile and worst case, and\n"
    "the share of configurations where a step makes things worse; writes\n"
    "  DIR/sphere_noh.csv        every configuration\n"
    "  DIR/sphere_noh_map.csv    means over (n.v, light elevation)\n"
    "  DIR/sphere_noh_map.png    where the step helps or hurts (and .gp scripts)\n"
    "  DIR/sphere_noh_by_nv.csv  mean shortfalls against n.v\n"
    "  DIR/sphere_noh_error.png  mean shortfall against n.v",
    options, NULL, NULL};

static void print_stats(const sphere_noh_stats *st)
{
    printf("%ld configurations, R inside the light (exact, 1) in %ld\n", st->configurations, st->r_inside);
    printf("shortfall of (N.H)^2 below the brute-force maximum, R outside:\n");
    printf("%-22s %12s %12s %12s %14s %14s  (than)\n", "", "mean", "99th pct", "worst", "worse", "better");
    for (int m = 0; m < NOH_METHODS; ++m) {
        const sphere_noh_row *r = &st->rows[m];
        printf("%-22s %12.4g %12.4g %12.4g %13.2f%% %13.2f%%  %s\n", r->method, r->mean, r->p99, r->worst,
               100.0 * r->share_worse, 100.0 * r->share_better, r->has_baseline ? r->baseline : "");
    }
}

int check_sphere_noh(int argc, char **argv)
{
    const char *dir = "sphere-noh";
    long steps = 16, rim_steps = 256;
    int status;
    if (cli_options_parse(&command, (void *[]){&dir, &steps, &rim_steps}, argc, argv, &status) != 0 ||
        (status = cli_make_output_dir(dir)) != 0)
        return status;
    sphere_noh_sweep sweep = {(int)steps, (int)steps, (int)steps, (int)steps, (int)rim_steps};
    sphere_noh_stats st;
    gt_error e;
    if (sphere_noh_study(&sweep, dir, &st, &e) != 0 || sphere_noh_plots(dir, &e) != 0)
        return cli_fail(&e);
    print_stats(&st);
    printf("written: %s/sphere_noh.csv, sphere_noh_map.csv, sphere_noh_map.png, sphere_noh_error.png\n", dir);
    return EXIT_OK;
}
