/* report/gnuplot_plot.c: a good script gives a PNG (and keeps its .gp script)
 * and an SVG of the same plot beside it, a broken one gives an error naming
 * the PNG and leaves no file behind, and so does a PNG or SVG that gnuplot
 * could not write whole (a file size limit, as a full disk). */
#include "report/gnuplot_plot.h"
#include "tests/check.h"

#include <dirent.h>
#include <signal.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

static int png_signature(const char *path)
{
    unsigned char head[8] = {0};
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    size_t n = fread(head, 1, 8, f);
    fclose(f);
    return n == 8 && memcmp(head, "\x89PNG\r\n\x1a\n", 8) == 0;
}

/* Whether the file holds an SVG document with `text` in it. */
static int svg_with(const char *path, const char *text)
{
    char buf[65536] = {0};
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    return strstr(buf, "<svg") != NULL && strstr(buf, text) != NULL;
}

static int leftovers(const char *dir)
{
    int found = 0;
    DIR *d = opendir(dir);
    for (struct dirent *entry; d && (entry = readdir(d));)
        found += strstr(entry->d_name, ".tmp-") != NULL;
    if (d)
        closedir(d);
    return found;
}

/* Under a file size limit of 16 KiB with SIGXFSZ ignored (writes past it
 * fail with EFBIG, as on a full disk; gnuplot exits 0 all the same): a PNG
 * larger than the limit, then a small PNG whose SVG (2000 samples) is
 * larger, each an error naming the file, the file not written, no
 * temporaries. In a child process, which the limit would otherwise outlive
 * the test in; returns the child's failed checks. */
static int limited_failures(const char *dir)
{
    pid_t child = fork();
    if (child == 0) {
        char png[1024], svg[1024];
        gt_error e;
        signal(SIGXFSZ, SIG_IGN);
        setrlimit(RLIMIT_FSIZE, &(struct rlimit){16384, 16384});
        snprintf(png, sizeof png, "%s/plot_limit.png", dir);
        remove(png);
        CHECK(gnuplot_render("set samples 2000\nplot sin(x) * x\n", png, 800, 600, &e) != 0);
        CHECK_MSG(strstr(e.message, "plot_limit.png: gnuplot could not write the whole PNG") != NULL, "%s", e.message);
        CHECK(!png_signature(png));
        snprintf(png, sizeof png, "%s/plot_limit_svg.png", dir);
        snprintf(svg, sizeof svg, "%s/plot_limit_svg.svg", dir);
        remove(svg);
        CHECK(gnuplot_render("set samples 2000\nplot sin(x) * x\n", png, 160, 120, &e) != 0);
        CHECK_MSG(strstr(e.message, "plot_limit_svg.svg: gnuplot could not write the whole SVG") != NULL, "%s",
                  e.message);
        CHECK(!svg_with(svg, "<svg"));
        remove(png);
        _exit(check_failures);
    }
    int status = -1;
    return child > 0 && waitpid(child, &status, 0) == child && WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

int main(void)
{
    if (!gnuplot_available()) {
        fprintf(stderr, "gnuplot not installed (setup.sh installs gnuplot-nox): skipped\n");
        return 77;
    }
    char png[1024], gp[1024], bad[1024], svg[1024], bad_svg[1024];
    snprintf(png, sizeof png, "%s/plot_test.png", check_tmp_dir());
    snprintf(gp, sizeof gp, "%s/plot_test.gp", check_tmp_dir());
    snprintf(bad, sizeof bad, "%s/plot_bad.png", check_tmp_dir());
    snprintf(svg, sizeof svg, "%s/plot_test.svg", check_tmp_dir());
    snprintf(bad_svg, sizeof bad_svg, "%s/plot_bad.svg", check_tmp_dir());
    remove(png);
    remove(bad);
    remove(svg);
    remove(bad_svg);
    gt_error e;
    CHECK_MSG(gnuplot_render("plot x*x title 'x^2'\n", png, 320, 240, &e) == 0, "%s", e.message);
    CHECK(png_signature(png));
    CHECK(svg_with(svg, "width=\"320\"") && svg_with(svg, "font-size=\"11"));
    FILE *script = fopen(gp, "r");
    CHECK(script != NULL);
    if (script)
        fclose(script);
    CHECK(gnuplot_render("plot nonsense_function(x)\n", bad, 320, 240, &e) != 0);
    CHECK_MSG(strstr(e.message, "plot_bad.png: gnuplot failed") != NULL, "%s", e.message);
    FILE *none = fopen(bad, "rb");
    CHECK(none == NULL);
    if (none)
        fclose(none);
    CHECK(!svg_with(bad_svg, "<svg"));
    CHECK_MSG(limited_failures(check_tmp_dir()) == 0, "a plot past the file size limit did not fail cleanly");
    CHECK(leftovers(check_tmp_dir()) == 0);
    return check_report("cli_gnuplot_plot");
}
