/* Plots through gnuplot; see gnuplot_plot.h. */
#define _GNU_SOURCE
#include "report/gnuplot_plot.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/atomic_file.h"

int gnuplot_available(void) { return system("gnuplot --version >/dev/null 2>&1") == 0; }

/* pngcairo draws anti-aliased lines; the libgd png terminal is the fallback. */
static const char *png_terminal(void)
{
    static const char *chosen = NULL;
    if (!chosen)
        chosen = system("gnuplot -e 'set terminal pngcairo' >/dev/null 2>&1") == 0 ? "pngcairo" : "png";
    return chosen;
}

/* path with its ".png" replaced by `extension` (".gp", ".svg"). */
static void sibling_path(const char *png_path, const char *extension, char *out, size_t size)
{
    size_t n = strlen(png_path);
    if (n > 4 && strcmp(png_path + n - 4, ".png") == 0)
        n -= 4;
    snprintf(out, size, "%.*s%s", (int)n, png_path, extension);
}

/* The terminal line of the PNG, or of the SVG (its font scaled with width). */
static char *terminal_line(int svg, int width, int height)
{
    char *text = NULL;
    int font = (GNUPLOT_SVG_FONT * width + 450) / 900;
    int rc = svg ? asprintf(&text, "set terminal svg size %d,%d font 'sans,%d' background '#ffffff'", width, height,
                            font < 11 ? 11 : font)
                 : asprintf(&text, "set terminal %s size %d,%d font ',10'", png_terminal(), width, height);
    return rc < 0 ? NULL : text;
}

/* The terminal and output lines, then the caller's plot commands. */
static char *full_script(const char *terminal, const char *script, const char *output)
{
    char *text = NULL;
    if (!terminal || asprintf(&text, "%s\nset output '%s'\n%s\nunset output\n", terminal, output, script) < 0)
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
    int sent = fputs(text, pipe) >= 0;
    int status = pclose(pipe);
    if (status == 0 && !sent)
        return gt_error_set(e, png_path, "cannot send the script to gnuplot");
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

/* Whether gnuplot's file at `path` is whole: a PNG ends with its IEND
 * chunk, an SVG with "</svg>" (and white space). gnuplot exits 0 when its
 * terminal could not write the file (a full disk, EFBIG): its status alone
 * does not tell. */
static int output_complete(const char *path, int svg)
{
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    unsigned char tail[64];
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    long size = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    long n = size < (long)sizeof tail ? size : (long)sizeof tail;
    int read = n > 0 && fseek(f, -n, SEEK_END) == 0 && fread(tail, 1, (size_t)n, f) == (size_t)n;
    fclose(f);
    if (!read)
        return 0;
    if (!svg)
        return n >= 12 && memcmp(tail + n - 12, iend, 12) == 0;
    while (n > 0 && (tail[n - 1] == '\n' || tail[n - 1] == '\r' || tail[n - 1] == ' '))
        --n;
    return n >= 6 && memcmp(tail + n - 6, "</svg>", 6) == 0;
}

/* Draws `script` into `path` (atomically) on the PNG or the SVG terminal;
 * with `kept`, the full script is also written there. */
static int render_to(const char *script, const char *path, int svg, int width, int height, const char *kept,
                     gt_error *e)
{
    atomic_file out;
    if (atomic_file_begin(&out, path, e) != 0)
        return -1;
    char log_path[ATOMIC_PATH_MAX + 8];
    snprintf(log_path, sizeof log_path, "%s.log", out.temp_path);
    char *terminal = terminal_line(svg, width, height);
    char *shown = kept ? full_script(terminal, script, path) : NULL, *run = full_script(terminal, script, out.temp_path);
    int rc = run && (shown || !kept) ? 0 : gt_error_set(e, path, "out of memory");
    if (rc == 0 && kept)
        rc = atomic_write_text(kept, shown, e);
    if (rc == 0)
        rc = run_gnuplot(run, log_path, path, e);
    if (rc == 0 && !output_complete(out.temp_path, svg))
        rc = gt_error_set(e, path, "gnuplot could not write the whole %s (disk full, or a file size limit?)",
                          svg ? "SVG" : "PNG");
    remove(log_path);
    free(terminal);
    free(shown);
    free(run);
    if (rc == 0)
        return atomic_file_commit(&out, e);
    atomic_file_abort(&out);
    return -1;
}

int gnuplot_render(const char *script, const char *png_path, int width, int height, gt_error *e)
{
    if (strchr(png_path, '\'') != NULL)
        return gt_error_set(e, png_path, "a path with a single quote cannot be given to gnuplot");
    if (!gnuplot_available())
        return gt_error_set(e, png_path, "gnuplot not found (Debian package gnuplot-nox)");
    char gp[ATOMIC_PATH_MAX], svg[ATOMIC_PATH_MAX];
    sibling_path(png_path, ".gp", gp, sizeof gp);
    sibling_path(png_path, ".svg", svg, sizeof svg);
    if (render_to(script, png_path, 0, width, height, gp, e) != 0)
        return -1;
    return render_to(script, svg, 1, width, height, NULL, e);
}
