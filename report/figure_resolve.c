/* report.html's figures settled at writing; see figure_resolve.h. */
#define _GNU_SOURCE
#include "report/figure_resolve.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "report/heatmap_colour_bar.h"
#include "report/html_text.h"

static int is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* The image to show for `path`: its .svg twin when dir holds one. */
static void put_source(FILE *f, const char *dir, const char *path)
{
    size_t n = strlen(path);
    char svg[8192];
    if (n > 4 && strcmp(path + n - 4, ".png") == 0) {
        snprintf(svg, sizeof svg, "%s/%.*s.svg", dir, (int)(n - 4), path);
        if (is_file(svg)) {
            html_put_escaped(f, svg + strlen(dir) + 1);
            return;
        }
    }
    html_put_escaped(f, path);
}

static void put_bar(FILE *f, const char *dir, const char *path)
{
    char file[8192], bar[2048];
    snprintf(file, sizeof file, "%s/%s", dir, path);
    if (heatmap_colour_bar(file, bar, sizeof bar))
        fputs(bar, f);
}

char *figures_resolve(const char *html, const char *dir)
{
    char *out = NULL, path[4096];
    size_t size = 0;
    FILE *f = open_memstream(&out, &size);
    if (!f)
        return NULL;
    for (const char *c = html; *c;) {
        const char *end = (*c == FIGURE_SRC[0] || *c == FIGURE_BAR[0]) ? strchr(c + 1, *c) : NULL;
        if (!end) {
            fputc(*c++, f);
            continue;
        }
        snprintf(path, sizeof path, "%.*s", (int)(end - c - 1), c + 1);
        if (*c == FIGURE_SRC[0])
            put_source(f, dir, path);
        else
            put_bar(f, dir, path);
        c = end + 1;
    }
    return fclose(f) == 0 ? out : (free(out), NULL);
}
