/* The height-fog medium against its mathematics: the closed-form optical
 * depth of a segment equals an adaptive quadrature of rho along it (up,
 * down, horizontal, H from 1 m to 1e9 m, through the floor), is symmetric
 * in its endpoints bit for bit, tends to d rho(y) for horizontal segments
 * and to d for H -> infinity; f(x) matches its series near 0;
 * the sun's transmittance is exp of the slanted column; bad parameters are
 * refused with a message naming them. */
#include <math.h>
#include <string.h>

#include "core/optics/height_fog_medium.h"
#include "core/sampling/quadrature.h"
#include "tests/check.h"

typedef struct {
    const height_fog_param *p;
    double y0, y1;
} segment;

/* rho at fraction s of the segment (per unit length of the parameter). */
static double rho_along(double s, void *ctx)
{
    const segment *g = ctx;
    return height_fog_density(g->p, g->y0 + s * (g->y1 - g->y0));
}

static void check_segment(double h, double y0, double y1, double d, double floor_y)
{
    height_fog_param p = height_fog_param_default();
    p.scale_height = h;
    p.floor_y = floor_y;
    segment g = {&p, y0, y1};
    double points[] = {0.0, floor_y > fmin(y0, y1) && floor_y < fmax(y0, y1) ? (floor_y - y0) / (y1 - y0) : 0.5, 1.0};
    double ref = d * quadrature_gk15_split(rho_along, &g, points, 3, 1e-13 * (1.0 + height_fog_density(&p, fmin(y0, y1))), NULL);
    double got = height_fog_segment_density(&p, y0, y1, d);
    CHECK_MSG(fabs(got - ref) <= 1e-9 * fabs(ref) + 1e-12, "H=%g y0=%g y1=%g d=%g: %.12g vs %.12g", h, y0, y1, d, got,
              ref);
    CHECK(got == height_fog_segment_density(&p, y1, y0, d));
}

static void check_segments(void)
{
    const double heights[] = {1.0, 30.0, 1000.0, 1e5, 1e9};
    for (int i = 0; i < 5; ++i) {
        check_segment(heights[i], 0.0, 200.0, 400.0, -INFINITY);   /* up */
        check_segment(heights[i], 500.0, -20.0, 3000.0, -INFINITY); /* down */
        check_segment(heights[i], 10.0, 10.0, 800.0, -INFINITY);   /* horizontal */
        check_segment(heights[i], 10.0, 10.0 + 1e-7, 800.0, -INFINITY);
        check_segment(heights[i], 300.0, -100.0, 700.0, 0.0);      /* through the floor */
    }
}

/* height_fog_distance_at inverts height_fog_segment_density. */
static void check_inverse(void)
{
    height_fog_param p = height_fog_param_default();
    const double heights[] = {1.0, 100.0, 1e4, 1e12, INFINITY}, dirs[] = {-0.9, -1e-9, 0.0, 1e-9, 0.3, 1.0};
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 6; ++j) {
            p.scale_height = heights[i];
            double y0 = 40.0, t = 250.0, y1 = y0 + dirs[j] * t;
            if (exp(-(y1 - y0) / heights[i]) < 1e-9)
                continue; /* the end lies where no fog is left to resolve it */
            double d_int = height_fog_segment_density(&p, y0, y1, t);
            double back = height_fog_distance_at(&p, y0, dirs[j], d_int);
            CHECK_MSG(fabs(back - t) <= 1e-9 * t, "H=%g dir_y=%g: %.12g vs %g", heights[i], dirs[j], back, t);
        }
    p.scale_height = 100.0;
    CHECK(height_fog_distance_at(&p, 0.0, 1.0, 100.0) == INFINITY); /* the whole column above holds 100 */
    CHECK(height_fog_distance_at(&p, 0.0, 1.0, 99.0) < INFINITY);
    /* Straight down from 100 km: H (rho(y) - rho(1e5)) = 1 at y = H ln H; no overflow. */
    CHECK_NEAR(height_fog_distance_at(&p, 1e5, -1.0, 1.0), 1e5 - 100.0 * log(100.0), 1e-6);
    p.floor_y = 0.0;
    CHECK(height_fog_distance_at(&p, 10.0, -1.0, 100.0) == INFINITY);  /* through the floor */
    CHECK(height_fog_distance_at(&p, -20.0, -0.5, 1.0) == INFINITY);   /* below it, going down */
    double from_below = height_fog_distance_at(&p, -20.0, 0.5, 0.5), from_floor = height_fog_distance_at(&p, 0.0, 0.5, 0.5);
    CHECK_NEAR(from_below, 40.0 + from_floor, 1e-9);
}

static void check_limits(void)
{
    height_fog_param p = height_fog_param_default();
    CHECK_NEAR(height_fog_segment_density(&p, 250.0, 250.0, 1e4), 1e4 * exp(-0.25), 1e-10 * 1e4);
    p.scale_height = INFINITY;
    CHECK(height_fog_segment_density(&p, -300.0, 5000.0, 7000.0) == 7000.0);
    p.scale_height = 100.0;
    p.floor_y = 0.0;
    CHECK(height_fog_segment_density(&p, -5.0, -1.0, 10.0) == 0.0);
    /* f(x) against its series 1 - x/2 + x^2/6 - x^3/24 for small x, and its limits. */
    for (double x = 1e-12; x < 1e-3; x *= 10.0)
        CHECK_NEAR(height_fog_mean_factor(x), 1.0 - x * (0.5 - x * (1.0 / 6.0 - x / 24.0)), 1e-14);
    CHECK(height_fog_mean_factor(0.0) == 1.0);
    CHECK_NEAR(height_fog_mean_factor(50.0), 1.0 / 50.0, 1e-15);
}

static void check_sun(void)
{
    height_fog_param p = height_fog_param_default();
    double t[3], beta_t[3];
    height_fog_extinction(&p, beta_t);
    height_fog_sun_transmittance(&p, 120.0, t);
    for (int c = 0; c < 3; ++c)
        CHECK_NEAR(t[c], exp(-beta_t[c] * 1000.0 * exp(-0.12) / sqrt(0.5)), 1e-6);
    p.sun_direction = v3(1.0f, 0.0f, 0.0f); /* on the horizon: the infinite layer blocks it */
    height_fog_sun_transmittance(&p, 120.0, t);
    CHECK(t[0] == 0.0 && t[2] == 0.0);
    p.beta_rs[0] = p.beta_rs[1] = p.beta_rs[2] = p.beta_ms = p.beta_ma = 0.0; /* no fog: 1 */
    height_fog_sun_transmittance(&p, 120.0, t);
    CHECK(t[0] == 1.0 && t[1] == 1.0);
}

/* Each bad parameter is refused and named. */
static void check_bad(void)
{
    gt_error e;
    height_fog_param p = height_fog_param_default();
    CHECK(height_fog_param_validate(&p, "fog", &e) == 0);
    struct { double *field; double value; const char *word; } cases[] = {
        {&p.beta_ms, -1e-6, "Mie scattering"}, {&p.beta_rs[1], NAN, "Rayleigh"},
        {&p.beta_ma, INFINITY, "absorption"},  {&p.scale_height, 0.0, "scale height"},
        {&p.scale_height, NAN, "scale height"}, {&p.mie_g, 1.0, "asymmetry"},
        {&p.amb_color[2], -0.5, "ambient"},    {&p.floor_y, NAN, "floor"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        double saved = *cases[i].field;
        *cases[i].field = cases[i].value;
        CHECK(height_fog_param_validate(&p, "fog", &e) != 0);
        CHECK_MSG(strstr(e.message, cases[i].word) && strncmp(e.message, "fog: ", 5) == 0, "%s", e.message);
        *cases[i].field = saved;
    }
    p.sun_direction = v3(0.0f, 2.0f, 0.0f);
    CHECK(height_fog_param_validate(&p, "fog", &e) != 0 && strstr(e.message, "sun direction"));
    p.sun_direction = v3(0.0f, -1.0f, 0.0f); /* below the horizon: valid, documented as unlit */
    CHECK(height_fog_param_validate(&p, "fog", &e) == 0);
}

int main(void)
{
    check_segments();
    check_inverse();
    check_limits();
    check_sun();
    check_bad();
    return check_report("test_height_fog_medium");
}
