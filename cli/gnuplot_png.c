#define _GNU_SOURCE
#include "cli/gnuplot_png.h"

#include <errno.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "core/atomic_file.h"

extern char **environ;

/* The script with the given output path; the caller frees it. */
static char *script_text(const char *output, int width, int height, const char *commands)
{
    const char *head = "set terminal pngcairo size %d,%d enhanced font 'sans,10'\nset output '%s'\n%s\n";
    size_t size = strlen(head) + strlen(output) + strlen(commands) + 64;
    char *text = malloc(size);
    if (text)
        snprintf(text, size, head, width, height, output, commands);
    return text;
}

static int run_gnuplot(const char *script_path, gt_error *e)
{
    char *argv[] = {"gnuplot", (char *)script_path, NULL};
    pid_t pid;
    int rc = posix_spawnp(&pid, "gnuplot", NULL, NULL, argv, environ);
    if (rc != 0)
        return gt_error_set(e, "gnuplot", "cannot run: %s (install gnuplot-nox)", strerror(rc));
    int status;
    if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return gt_error_set(e, script_path, "gnuplot failed on this script");
    return 0;
}

int gnuplot_png(const char *png_path, int width, int height, const char *commands, gt_error *e)
{
    char script_path[ATOMIC_PATH_MAX];
    size_t len = strlen(png_path);
    if (len < 5 || strcmp(png_path + len - 4, ".png") != 0 || len + 1 > sizeof script_path)
        return gt_error_set(e, png_path, "a plot's name must end in .png");
    snprintf(script_path, sizeof script_path, "%.*s.gp", (int)(len - 4), png_path);
    atomic_file png;
    if (atomic_file_begin(&png, png_path, e) != 0)
        return -1;
    /* The script run points at the temporary PNG; the one kept, at the final. */
    char *run_text = script_text(png.temp_path, width, height, commands);
    char *kept_text = script_text(png_path, width, height, commands);
    char run_path[ATOMIC_PATH_MAX + 8];
    snprintf(run_path, sizeof run_path, "%s.run", png.temp_path);
    int rc = -1;
    if (!run_text || !kept_text)
        gt_error_set(e, png_path, "out of memory");
    else if (atomic_write_text(run_path, run_text, e) == 0) {
        rc = run_gnuplot(run_path, e);
        remove(run_path);
        if (rc == 0)
            rc = atomic_file_commit(&png, e);
        if (rc == 0)
            rc = atomic_write_text(script_path, kept_text, e);
    }
    if (rc != 0)
        atomic_file_abort(&png);
    free(run_text);
    free(kept_text);
    return rc;
}
