/* The atmosphere LUTs under the talk's parametrization as files
 * (atmosphere/atmosphere_luts_study.h atmosphere_luts_write_tables, what `gtlab lut
 * atmosphere --parametrization` and the study write;
 * atmosphere/atmosphere_luts_writers.h): for Yusov 2013's and Bruneton &
 * Neyret's mappings at the talk's spatial in-scatter size,
 *   - the EXRs' bytes are the same with 1 and 2 threads (Yusov's);
 *   - they read back (atmosphere_luts_read_exr) to the very table the
 *     study's sky rows evaluate (atmosphere_luts_build_parametrized from the
 *     same solution: every texel bit for bit), and the sky's error through
 *     the read-back table is the study's number exactly;
 *   - their headers name the parametrization, its axes and the sizes;
 *   - a file read as another parametrization is refused, naming the file.
 * And the sizes table's decision (atmosphere_luts_row_decision): within,
 * beyond or undecided by the 95% interval of the 95th percentile. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "atmosphere/atmosphere_luts_writers.h"
#include "atmosphere/atmosphere_luts_study.h"
#include "tests/check.h"

/* The talk's in-scatter (theta_s, theta_v, y) at one weather (t = 0: one
 * precomputation per build, the test stays fast), small sun and sky tables. */
static const atmosphere_lut_sizes SIZES = {{8, 64, 8, 1}, {8, 1, 2, 1}, {8, 1, 2, 1}};

static char *read_bytes(const char *path, long *size)
{
    FILE *f = fopen(path, "rb");
    char *bytes = NULL;
    *size = -1;
    if (f && fseek(f, 0, SEEK_END) == 0 && (*size = ftell(f)) > 0 && fseek(f, 0, SEEK_SET) == 0 &&
        (bytes = malloc((size_t)*size)) && fread(bytes, 1, (size_t)*size, f) != (size_t)*size)
        free(bytes), bytes = NULL;
    if (f)
        fclose(f);
    return bytes;
}

static void same_bytes(const char *a_dir, const char *b_dir, const char *name)
{
    char a[4096], b[4096];
    long na, nb;
    snprintf(a, sizeof a, "%s/%s", a_dir, name), snprintf(b, sizeof b, "%s/%s", b_dir, name);
    char *x = read_bytes(a, &na), *y = read_bytes(b, &nb);
    CHECK_MSG(x && y && na == nb && memcmp(x, y, (size_t)na) == 0, "%s differs between 1 and 2 threads", name);
    free(x), free(y);
}

static void check_header(const char *dir, atmosphere_lut_parametrization kind)
{
    char name[128], path[4096];
    image img;
    gt_error e;
    atmosphere_luts_exr_name(kind, ATMOSPHERE_TABLE_INSCATTER, name, sizeof name);
    CHECK(strstr(name, atmosphere_lut_parametrization_tag(kind)) != NULL);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    CHECK(exr_read(path, &img, &e) == 0);
    const char *tag = image_get_attribute(&img, ATTR_LUT_PARAMETRIZATION);
    const char *axes = image_get_attribute(&img, ATTR_LUT), *sizes = image_get_attribute(&img, ATTR_LUT_SIZES);
    CHECK(tag && strcmp(tag, atmosphere_lut_parametrization_tag(kind)) == 0);
    CHECK(axes && strstr(axes, atmosphere_lut_axes_description(kind)));
    CHECK(axes && strstr(axes, kind == ATMOSPHERE_PARAM_YUSOV ? "Yusov 2013" : "Bruneton & Neyret 2008"));
    CHECK(sizes && strcmp(sizes, "8 64 8 1") == 0);
    image_free(&img);
}

/* threads: also written with 1 thread and compared (2 always). */
static void test_files(atmosphere_lut_parametrization kind, const atmosphere_solution *s, int compare_threads)
{
    char one[2048], two[2048], name[128];
    gt_error e;
    snprintf(one, sizeof one, "%s/atmosphere_%s_1", check_tmp_dir(), atmosphere_lut_parametrization_tag(kind));
    snprintf(two, sizeof two, "%s/atmosphere_%s_2", check_tmp_dir(), atmosphere_lut_parametrization_tag(kind));
    mkdir(one, 0755), mkdir(two, 0755);
    CHECK(atmosphere_luts_write_tables(one, &SIZES, kind, 2, NULL, &e) == 0);
    if (compare_threads) {
        CHECK(atmosphere_luts_write_tables(two, &SIZES, kind, 1, NULL, &e) == 0);
        for (int table = 0; table < ATMOSPHERE_TABLES; ++table)
            atmosphere_luts_exr_name(kind, table, name, sizeof name), same_bytes(one, two, name);
    }
    check_header(one, kind);

    /* the table the study's sky row evaluates: the in-scatter table alone, from the same solution */
    atmosphere_lut_sizes study_sizes = {{8, 64, 8, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}};
    atmosphere_luts study, back;
    char msg[256];
    CHECK(atmosphere_luts_build_parametrized(&study, s, 1, &study_sizes, kind, 2, msg, sizeof msg) == 0);
    CHECK_MSG(atmosphere_luts_read_exr(one, kind, &back, &e) == 0, "%s", e.message);
    CHECK(memcmp(back.sizes.inscatter, study.sizes.inscatter, sizeof back.sizes.inscatter) == 0);
    size_t floats = 6u * 8 * 64 * 8;
    CHECK_MSG(memcmp(back.table[ATMOSPHERE_TABLE_INSCATTER], study.table[ATMOSPHERE_TABLE_INSCATTER],
                     floats * sizeof(float)) == 0,
              "%s: the file's in-scatter texels are not the study's", atmosphere_lut_parametrization_name(kind));
    atmosphere_sky_sample sample;
    atmosphere_error_stats a, b;
    CHECK(atmosphere_sky_sample_build(&sample, s, 1, 300, 0.0, ATMOSPHERE_TWILIGHT_THETA_S, 5u, 2) == 0);
    CHECK(atmosphere_sky_errors(&study, &sample, &a) == 0 && atmosphere_sky_errors(&back, &sample, &b) == 0);
    CHECK_MSG(a.p95 == b.p95 && a.max == b.max && a.rms == b.rms && a.p95_se == b.p95_se,
              "sky p95 %.9g (study) vs %.9g (file)", a.p95, b.p95);
    CHECK(a.p95 > 0.0); /* a real table: interpolation has an error */
    atmosphere_sky_sample_free(&sample);
    atmosphere_luts_free(&study), atmosphere_luts_free(&back);

    /* read as the other nonlinear parametrization: refused, naming the file and the attribute */
    atmosphere_lut_parametrization other = kind == ATMOSPHERE_PARAM_YUSOV ? ATMOSPHERE_PARAM_BRUNETON
                                                                          : ATMOSPHERE_PARAM_YUSOV;
    char path[4096], wrong[4096];
    atmosphere_luts_exr_name(kind, ATMOSPHERE_TABLE_INSCATTER, name, sizeof name);
    snprintf(path, sizeof path, "%s/%s", one, name);
    atmosphere_luts_exr_name(other, ATMOSPHERE_TABLE_INSCATTER, name, sizeof name);
    snprintf(wrong, sizeof wrong, "%s/%s", one, name);
    CHECK(rename(path, wrong) == 0);
    CHECK(atmosphere_luts_read_exr(one, other, &back, &e) != 0 && strstr(e.message, ATTR_LUT_PARAMETRIZATION) &&
          strstr(e.message, wrong));
    CHECK(back.table[0] == NULL && back.table[1] == NULL && back.table[2] == NULL);
}

static atmosphere_luts_row row(double p95, double se)
{
    atmosphere_luts_row r;
    memset(&r, 0, sizeof r);
    r.error.total.p95 = p95, r.error.total.p95_se = se, r.error.quadrature.p95 = 1e-3;
    return r;
}

static void test_decision(void)
{
    atmosphere_luts_row within = row(0.010, 0.004), beyond = row(0.05, 0.01), straddle = row(0.018, 0.002);
    atmosphere_luts_row floor = row(0.030, 0.001);
    floor.error.quadrature.p95 = 0.04; /* the quadrature's own floor above 2% */
    CHECK(atmosphere_luts_row_decision(&within) == 1 && atmosphere_luts_row_suffices(&within));
    CHECK(atmosphere_luts_row_decision(&beyond) == -1 && !atmosphere_luts_row_suffices(&beyond));
    CHECK(atmosphere_luts_row_decision(&straddle) == 0 && !atmosphere_luts_row_suffices(&straddle));
    CHECK(atmosphere_luts_row_decision(&floor) == 1);
}

int main(void)
{
    atmosphere_model m = atmosphere_model_default();
    atmosphere_solution s;
    CHECK(atmosphere_solve(&m, 0.0, 2, &s) == 0);
    test_files(ATMOSPHERE_PARAM_YUSOV, &s, 1);
    test_files(ATMOSPHERE_PARAM_BRUNETON, &s, 0);
    atmosphere_solution_free(&s);
    test_decision();
    return check_report("studies_atmosphere_lut_files");
}
