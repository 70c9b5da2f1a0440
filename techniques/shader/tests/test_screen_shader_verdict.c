/* The screen-shaders table's verdict (shader/screen_shader_section.h):
 * "better" or "worse" only past significance AND a visible margin. The case
 * of issue 42: gtlab's own GLSL GTAO against its C port, a paired
 * difference of squared errors of 3.6e-6 that is significant, with RMSEs
 * that differ by far less than one 8-bit code value, is "no visible
 * difference", not "worse". */
#include "report/claim_thresholds.h"
#include "shader/screen_shader_section.h"
#include "tests/check.h"

#include <string.h>

static screen_shader_variant variant(double rmse, double mse_difference, double se)
{
    return (screen_shader_variant){.rmse = rmse, .vs_gtao = {.mean = mse_difference, .se = se, .blocks = 4000}};
}

int main(void)
{
    const screen_shader_variant c = variant(0.1000, 0.0, 0.0);
    const double code = CLAIM_ONE_CODE_VALUE_8BIT;
    /* rmse^2 - 0.1^2 = 3.6e-6: RMSE 0.100018, far inside one code value (0.0039) */
    screen_shader_variant glsl = variant(0.100018, 3.6e-6, 1e-7);
    CHECK(strcmp(screen_shader_verdict(&glsl, &c), "no visible difference") == 0);
    CHECK(strcmp(screen_shader_verdict(&c, &c), "-") == 0);
    /* past the margin: the sign of the paired difference decides, if significant */
    screen_shader_variant worse = variant(0.1 + 2 * code, 0.0016, 1e-4), better = variant(0.1 - 2 * code, -0.0015, 1e-4);
    CHECK(strcmp(screen_shader_verdict(&worse, &c), "worse") == 0);
    CHECK(strcmp(screen_shader_verdict(&better, &c), "better") == 0);
    screen_shader_variant noisy = variant(0.1 + 2 * code, 0.0016, 0.01);
    CHECK(strcmp(screen_shader_verdict(&noisy, &c), "not significant") == 0);
    /* just inside and just outside the margin */
    screen_shader_variant inside = variant(0.1 + 0.99 * code, 0.0008, 1e-6), outside = variant(0.1 + 1.01 * code, 0.0008, 1e-6);
    CHECK(strcmp(screen_shader_verdict(&inside, &c), "no visible difference") == 0);
    CHECK(strcmp(screen_shader_verdict(&outside, &c), "worse") == 0);
    return check_report("test_screen_shader_verdict");
}
