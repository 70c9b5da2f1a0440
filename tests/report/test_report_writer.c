/* report/report_writer.c: the report's Markdown and HTML say the same thing;
 * findings gathered while stages run land in one "At a glance" section right
 * after the introduction, before every stage's section; HTML special
 * characters are escaped; a report without findings has no such section. */
#include "report/report_writer.h"
#include "tests/check.h"

#include <stdlib.h>
#include <string.h>

static char *read_all(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = malloc((size_t)n + 1);
    if (text && fread(text, 1, (size_t)n, f) != (size_t)n) {
        free(text);
        text = NULL;
    }
    if (text)
        text[n] = '\0';
    fclose(f);
    return text;
}

/* Whether `first` occurs in `text`, and before `second`. */
static int occurs_before(const char *text, const char *first, const char *second)
{
    const char *a = text ? strstr(text, first) : NULL, *b = text ? strstr(text, second) : NULL;
    return a && b && a < b;
}

static void write_and_read(report *r, char **md, char **html)
{
    char path[2048];
    gt_error e;
    CHECK(report_write(r, check_tmp_dir(), &e) == 0);
    snprintf(path, sizeof path, "%s/report.md", check_tmp_dir());
    *md = read_all(path);
    snprintf(path, sizeof path, "%s/report.html", check_tmp_dir());
    *html = read_all(path);
    CHECK(*md && *html);
}

static void test_findings_after_introduction(void)
{
    report r;
    report_init(&r, "title");
    report_paragraph(&r, "introduction");
    report_findings_here(&r);
    report_heading(&r, 2, "Stage one");
    report_finding(&r, "AO", "error %.2f < 1", 0.25);
    report_heading(&r, 2, "Stage two");
    report_finding(&r, "GTAO", "second");
    char *md, *html;
    write_and_read(&r, &md, &html);
    CHECK(occurs_before(md, "introduction", "## At a glance"));
    CHECK(occurs_before(md, "## At a glance", "- **[AO](#stage-one)**: error 0.25 < 1"));
    CHECK(occurs_before(md, "- **[AO](#stage-one)**: error 0.25 < 1", "- **[GTAO](#stage-two)**: second"));
    CHECK(occurs_before(md, "- **[GTAO](#stage-two)**: second", "## Contents"));
    CHECK(occurs_before(md, "## Contents", "- [Stage one](#stage-one)\n- [Stage two](#stage-two)\n"));
    CHECK(occurs_before(md, "- [Stage two](#stage-two)", "## Stage one"));
    CHECK(occurs_before(html, "<p>introduction</p>", "<h2 id=\"at-a-glance\">At a glance</h2>"));
    CHECK(occurs_before(html, "<li><b><a href=\"#stage-one\">AO</a></b>: error 0.25 &lt; 1</li>",
                        "<h2 id=\"contents\">Contents</h2>"));
    CHECK(occurs_before(html, "<li><a href=\"#stage-two\">Stage two</a></li>", "<h2 id=\"stage-one\">Stage one</h2>"));
    CHECK(html && strstr(html, "</ul>") && strstr(html, "</body></html>"));
    free(md);
    free(html);
    report_free(&r);
}

static void test_no_findings_no_section(void)
{
    report r;
    report_init(&r, "title");
    report_findings_here(&r);
    report_heading(&r, 2, "Stage");
    char *md, *html;
    write_and_read(&r, &md, &html);
    CHECK(md && !strstr(md, "At a glance") && strstr(md, "## Stage"));
    CHECK(html && !strstr(html, "At a glance"));
    free(md);
    free(html);
    report_free(&r);
}

/* Anchors follow GitHub's rule for Markdown headings: lowercase, spaces to
 * '-', punctuation dropped, repeats numbered; the names the report inserts
 * itself ("At a glance", "Contents") are taken; every HTML id is unique. */
static void test_anchors(void)
{
    report r;
    report_init(&r, "title");
    report_findings_here(&r);
    report_heading(&r, 2, "Height fog (Decima 2017): 1.5x <faster>");
    report_heading(&r, 3, "Item 9: fast_acos");
    report_heading(&r, 2, "Contents");
    report_heading(&r, 3, "Item 9: fast_acos");
    char *md, *html;
    write_and_read(&r, &md, &html);
    CHECK(html && strstr(html, "<h2 id=\"height-fog-decima-2017-15x-faster\">Height fog (Decima 2017): 1.5x &lt;faster&gt;</h2>"));
    CHECK(html && strstr(html, "<h3 id=\"item-9-fast_acos\">") && strstr(html, "<h3 id=\"item-9-fast_acos-1\">"));
    CHECK(html && strstr(html, "<h2 id=\"contents-1\">Contents</h2>"));
    CHECK(md && strstr(md, "- [Height fog (Decima 2017): 1.5x <faster>](#height-fog-decima-2017-15x-faster)\n"));
    CHECK(md && strstr(md, "- [Contents](#contents-1)\n"));
    free(md);
    free(html);
    report_free(&r);
}

/* A '|' inside a table cell is escaped in Markdown (it would split the
 * cell) and left as it is in HTML. */
static void test_pipe_in_cell(void)
{
    report r;
    report_init(&r, "title");
    const char *headers[2] = {"what", "mean |x|"};
    const char *cells[2] = {"a", "|e| = 1"};
    report_table_begin(&r, 2, headers);
    report_table_row(&r, cells);
    report_table_end(&r);
    char *md, *html;
    write_and_read(&r, &md, &html);
    CHECK(md && strstr(md, "| a | \\|e\\| = 1 |") && strstr(md, "mean \\|x\\|"));
    CHECK(html && strstr(html, "<td>|e| = 1</td>"));
    free(md);
    free(html);
    report_free(&r);
}

int main(void)
{
    test_pipe_in_cell();
    test_findings_after_introduction();
    test_no_findings_no_section();
    test_anchors();
    return check_report("test_report_writer");
}
