/* `gtlab render fog`: transmittance and in-scattered radiance of the height
 * fog in front of each surface (techniques/height_fog/height_fog_integrator.h). */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/number_parse.h"
#include "core/reference_schema.h"
#include "height_fog/height_fog_integrator.h"
#include "raytracer/reference_render.h"

_Static_assert(offsetof(height_fog_settings, header) == 0, "the header comes first");

static height_fog_settings *settings_of(const reference_request *rq)
{
    return (height_fog_settings *)reference_settings_of(rq, &reference_quantity_fog);
}

static int parse_weather(reference_request *rq, const char *value, gt_error *e)
{
    height_fog_param p;
    if (height_fog_weather(value, 45.0, &p) != 0)
        return gt_error_set(e, "--fog-weather", "'%s' is neither sunny nor dense", value);
    snprintf(settings_of(rq)->weather, sizeof settings_of(rq)->weather, "%s", value);
    return 0;
}

static int parse_elevation(reference_request *rq, const char *value, gt_error *e)
{
    return parse_real_in("--fog-sun-elevation", value, -90.0, 90.0, &settings_of(rq)->sun_elevation_deg, e);
}

static int parse_scattering(reference_request *rq, const char *value, gt_error *e)
{
    if (height_fog_scattering_parse(value, &settings_of(rq)->scattering) != 0)
        return gt_error_set(e, "--fog-scattering", "'%s' is not quadrature, single or multiple", value);
    return 0;
}

static int parse_no_extinction(reference_request *rq, const char *value, gt_error *e)
{
    (void)value, (void)e;
    settings_of(rq)->no_sun_extinction = 1;
    return 0;
}

static int parse_no_shadows(reference_request *rq, const char *value, gt_error *e)
{
    (void)value, (void)e;
    settings_of(rq)->no_shadows = 1;
    return 0;
}

static const reference_option weather_option = {
    .name = "fog-weather", .value = "W", .help = "sunny (default) or dense", .parse = parse_weather};
static const reference_option elevation_option = {
    .name = "fog-sun-elevation", .value = "DEG", .help = "the sun's elevation (default 25)", .parse = parse_elevation};
static const reference_option scattering_option = {
    .name = "fog-scattering",
    .value = "S",
    .help = "multiple (default; path tracing), single (Monte\n"
            "Carlo) or quadrature (single scattering by gk15)",
    .parse = parse_scattering,
};
static const reference_option no_extinction_option = {
    .name = "fog-no-sun-extinction",
    .help = "the sun reaches every point unattenuated by the\nfog (the published model's assumption)",
    .parse = parse_no_extinction,
};
static const reference_option no_shadows_option = {
    .name = "fog-no-shadows",
    .help = "the scene neither shadows the fog from the sun\nnor blocks scattered light",
    .parse = parse_no_shadows,
};

void height_fog_settings_default(height_fog_settings *s)
{
    *s = (height_fog_settings){.header = {&reference_quantity_fog}, .weather = "sunny", .sun_elevation_deg = 25.0,
                        .scattering = HEIGHT_FOG_MULTIPLE, .max_scatterings = 1024};
}

static void set_defaults(reference_request *rq)
{
    height_fog_settings_default(settings_of(rq));
}

static int prepare(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    height_fog_plan *plan = malloc(sizeof *plan);
    if (!plan)
        return gt_error_set(e, pass->scene_spec, "out of memory");
    const height_fog_settings *s = settings_of(pass->req);
    if (!s || height_fog_plan_init(plan, s, pass->es, &pass->gb->view, e) != 0) {
        free(plan);
        return s ? -1 : gt_error_set(e, "fog", "no settings");
    }
    *state = plan;
    *it = height_fog_integrator(pass->es, plan);
    return 0;
}

static int write_settings(const reference_request *rq, image *out)
{
    const height_fog_settings *s = settings_of(rq);
    return reference_set_attributef(out, ATTR_SETTINGS,
                                    "weather=%s sun_elevation_deg=%.9g scattering=%s sun_extinction=%s shadows=%s "
                                    "max_scatterings=%d target_stderr=%.9g",
                                    s->weather, s->sun_elevation_deg, height_fog_scattering_name(s->scattering),
                                    s->no_sun_extinction ? "off" : "on", s->no_shadows ? "off" : "on",
                                    s->max_scatterings, rq->sampling.target_stderr);
}

const reference_quantity_descriptor reference_quantity_fog = {
    .name = "fog",
    .help = "the G-buffer plus the height fog of the Decima talk in front of\n"
            "each surface: fog.T.R/G/B (transmittance, closed form) and fog.L.R/G/B\n"
            "(sun + ambient light the fog scatters to the camera, with .stderr;\n"
            "composite as background * T + L); with --fog-scattering quadrature\n"
            "also fog_quadrature_error.R/G/B",
    .options = (const reference_option *const[]){&weather_option, &elevation_option, &scattering_option,
                                                 &no_extinction_option, &no_shadows_option, NULL},
    .settings_size = sizeof(height_fog_settings),
    .set_defaults = set_defaults,
    .prepare = prepare,
    .release = free,
    .write_settings = write_settings,
};
