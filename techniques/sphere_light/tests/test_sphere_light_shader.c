/* One source for the sphere light's C and shaders: the generated HLSL and
 * GLSL are sphere_light/sphere_light.inc verbatim and compile; the shader part of
 * the .inc, compiled here as C, agrees with the C functions (GetNoHSquared
 * bit for bit, EvaluateSphericalAreaGGX to float rounding of its own
 * visibility); and no other sphere-light source spells the formulas. */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tests/check.h"
#include "tests/source_text.h"
#include "sphere_light/sphere_light.h"
#include "sphere_light/sphere_light_shader.h"

/* The shaders' half of the .inc, as C (with the published constants). */
#define SPHERE_LIGHT_SHADER
#define SPHERE_RADIUS_REDUCTION 0.25f
#define SPHERE_NORM_SCALE 0.25f
#define SPHERE_NORM_ALPHA 3.0f
#define SPHERE_NORM_EPS 0.001f
#define SPHERE_MIN_RADIUS_TAN 0.001f
#include "sphere_light/sphere_light_c.h"
#include "sphere_light/sphere_light.inc"


static void test_embedded_text_is_the_file(void)
{
    char *text = read_text(GTLAB_SOURCE_DIR "/techniques/sphere_light/sphere_light.inc");
    CHECK(text != NULL && strcmp(text, sphere_light_inc_text) == 0);
    free(text);
}

/* A fragment shader calling both entry points, compiled by glslangValidator. */
static int compiles(shader_language language)
{
    decima_sphere_constants k = decima_sphere_published();
    char *source = sphere_light_shader_source(language, &k, "test"), path[4096], command[16384];
    const char *tmp = getenv("GTLAB_TEST_TMP") ? getenv("GTLAB_TEST_TMP") : "/tmp";
    CHECK(source != NULL && strstr(source, sphere_light_inc_text) != NULL);
    snprintf(path, sizeof path, "%s/sphere_light_shader.%s", tmp, language == SHADER_HLSL ? "hlsl" : "frag");
    FILE *f = fopen(path, "w");
    if (!f || !source)
        return 0;
    if (language == SHADER_GLSL)
        fprintf(f, "#version 450\n%s\nlayout(location = 0) in vec4 v;\nlayout(location = 0) out vec4 o;\n"
                   "void main() { o = vec4(EvaluateSphericalAreaGGX(v.x, v.y, v.z, v.w, 0.1, 0.3, vec3(0.04)), "
                   "GetNoHSquared(0.1, v.x, v.y, v.z)); }\n",
                source);
    else
        fprintf(f, "%s\nfloat4 main(float4 v : TEXCOORD0) : SV_Target { return float4(EvaluateSphericalAreaGGX("
                   "v.x, v.y, v.z, v.w, 0.1, 0.3, float3(0.04, 0.04, 0.04)), GetNoHSquared(0.1, v.x, v.y, v.z)); }\n",
                source);
    fclose(f);
    free(source);
    snprintf(command, sizeof command, "glslangValidator %s %s -o %s.spv >%s.log 2>&1",
             language == SHADER_HLSL ? "-D -V -e main -S frag" : "-V", path, path, path);
    return system(command) == 0;
}

/* The shader functions against the C ones over a grid of configurations. */
static void test_shader_functions_match_c(void)
{
    const decima_sphere_constants k = decima_sphere_published();
    double worst = 0.0;
    for (int a = 1; a < 10; ++a)
        for (int b = 1; b < 10; ++b)
            for (int c = 0; c < 8; ++c)
                for (int r = 1; r < 6; ++r) {
                    float nl = a / 10.0f, nv = b / 10.0f, vl = -0.9f + 0.25f * c, rt = 0.02f * r * r;
                    float ldoth = sqrtf(fmaxf(0.0f, 0.5f + 0.5f * vl)), alpha = 0.05f + 0.1f * r;
                    CHECK(GetNoHSquared(rt, nl, nv, vl) == sphere_noh_squared_decima(rt, nl, nv, vl));
                    double want = decima_sphere_ggx(nl, nv, vl, ldoth, rt, alpha, 0.04f, &k, 1);
                    double got = EvaluateSphericalAreaGGX(nl, nv, vl, ldoth, rt, alpha, 0.04f);
                    worst = fmax(worst, fabs(got - want) / fmax(want, 1e-6));
                }
    CHECK_MSG(worst < 1e-5, "relative difference %g", worst);
    for (int a = 1; a < 10; ++a)
        for (int b = 1; b < 10; ++b) {
            double nv = a / 10.0, nl = b / 10.0, alpha = 0.1 * a;
            double want = ggx_smith_g2(nv, nl, alpha) / (4.0 * nl * nv);
            CHECK_NEAR(sl_ggx_visibility((float)nv, (float)nl, (float)alpha), want, 1e-5 * want);
        }
}

/* Fingerprints of the formulas (and of the old hand-written HLSL copy) that
 * only sphere_light/sphere_light.inc may contain. */
static void test_no_second_copy(void)
{
    static const char *const files[] = {
        "techniques/sphere_light/sphere_light.c", "techniques/sphere_light/sphere_light_shader.c",
        "techniques/sphere_light/sphere_light_cli.c", "techniques/sphere_light/sphere_light_study.c"};
    static const char *const prints[] = {"NoLVTr", "no_b * d0", "0.25f * s", "norm_scale * radius_over_distance",
                                         "rsqrt(", "GetGGXVisibility"};
    check_no_file_spells(files, sizeof files / sizeof files[0], prints, sizeof prints / sizeof prints[0]);
}

int main(void)
{
    test_embedded_text_is_the_file();
    CHECK_MSG(compiles(SHADER_GLSL), "generated GLSL does not compile (see the .log beside it)");
    CHECK_MSG(compiles(SHADER_HLSL), "generated HLSL does not compile (see the .log beside it)");
    test_shader_functions_match_c();
    test_no_second_copy();
    return check_report("sphere_light_shader");
}
