/* Plots through gnuplot; see gnuplot_plot.h. */
#define _GNU_SOURCE
#include "report/gnuplot_plot.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/atomic_file.h"

int gnuplot_available(void) { return system("gnuplot --version >/dev/null 2>&1") == 0; }

/* pngcairo draws anti-aliased lines; the libgd png terminal is the fallback. */
static const char *png_terminal(void)
{
    static const char *chosen = NULL;
    if (!chosen)
        chosen = system("gnuplot -e 'set terminal pngcairo' >/dev/null 2>&1") == 0 ? "pngcairo" : "png";
    return chosen;
}

/* The script file's path: png_path with .gp for .png. */
static void script_path(const char *png_path, char *out, size_t size)
{
    size_t n = strlen(png_path);
    if (n > 4 && strcmp(png_path + n - 4, ".png") == 0)
        n -= 4;
    snprintf(out, size, "%.*s.gp", (int)n, png_path);
}

/* The terminal and output lines, then the caller's plot commands. */
static char *full_script(const char *script, const char *output, int width, int height)
{
    char *text = NULL;
    if (asprintf(&text, "set terminal %s size %d,%d font ',10'\nset output '%s'\n%s\nunset output\n", png_terminal(),
                 width, height, output, script) < 0)
        return NULL;
    return text;
}

/* Runs gnuplot on `text` through a pipe; its stderr goes to log_path. */
static int run_gnuplot(const char *text, const char *log_path, const char *png_path, gt_error *e)
{
    char *command = NULL;
    if (asprintf(&command, "gnuplot >/dev/null 2>'%s'", log_path) < 0)
        return gt_error_set(e, png_path, "out of memory");
    FILE *pipe = popen(command, "w");
    free(command);
    if (!pipe)
        return gt_error_set(e, png_path, "cannot run gnuplot");
    fputs(text, pipe);
    int status = pclose(pipe);
    if (status == 0)
        return 0;
    char line[256] = "no message";
    FILE *log = fopen(log_path, "r");
    while (log && fgets(line, sizeof line, log))
        if (strstr(line, "rror") || strstr(line, "line"))
            break;
    if (log)
        fclose(log);
    line[strcspn(line, "\n")] = '\0';
    return gt_error_set(e, png_path, "gnuplot failed: %s", line + strspn(line, " \t"));
}

int gnuplot_render(const char *script, const char *png_path, int width, int height, gt_error *e)
{
    if (strchr(png_path, '\'') != NULL)
        return gt_error_set(e, png_path, "a path with a single quote cannot be given to gnuplot");
    if (!gnuplot_available())
        return gt_error_set(e, png_path, "gnuplot not found (Debian package gnuplot-nox)");
    atomic_file png;
    if (atomic_file_begin(&png, png_path, e) != 0)
        return -1;
    char gp[ATOMIC_PATH_MAX], log_path[ATOMIC_PATH_MAX + 8];
    script_path(png_path, gp, sizeof gp);
    snprintf(log_path, sizeof log_path, "%s.log", png.temp_path);
    char *kept = full_script(script, png_path, width, height), *run = full_script(script, png.temp_path, width, height);
    int rc = kept && run ? 0 : gt_error_set(e, png_path, "out of memory");
    if (rc == 0)
        rc = atomic_write_text(gp, kept, e);
    if (rc == 0)
        rc = run_gnuplot(run, log_path, png_path, e);
    remove(log_path);
    free(kept);
    free(run);
    if (rc == 0)
        return atomic_file_commit(&png, e);
    atomic_file_abort(&png);
    return -1;
}
