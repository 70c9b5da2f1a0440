/* `gtlab render ao`: ambient occlusion and bent normals traced in the 3-D
 * scene (techniques/ao/ao_integrator.h). */
#include "ao/ao_quantity.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "core/number_parse.h"
#include "core/reference_schema.h"
#include "ao/ao_integrator.h"

_Static_assert(offsetof(ao_render_settings, header) == 0, "the header comes first");

ao_render_settings ao_render_settings_defaults(void)
{
    return (ao_render_settings){{QUANTITY_AO}, INFINITY, 0.0f, AO_CONTROL_VARIATE_NONE};
}

static ao_render_settings *settings_of(const reference_request *rq)
{
    return (ao_render_settings *)reference_settings_of(rq, QUANTITY_AO);
}

/* rq's settings, or the defaults when it carries none of ao's. */
static ao_render_settings settings_or_defaults(const reference_request *rq)
{
    const ao_render_settings *s = settings_of(rq);
    return s ? *s : ao_render_settings_defaults();
}

int ao_parse_max_distance(const char *value, float *max_distance, gt_error *e)
{
    double d;
    if (parse_real_in("--max-distance", value, 1e-30, 1e30, &d, e) != 0)
        return -1;
    *max_distance = (float)d;
    return 0;
}

static int parse_max_distance(reference_request *rq, const char *value, gt_error *e)
{
    return ao_parse_max_distance(value, &settings_of(rq)->max_distance, e);
}

static const reference_option option_max_distance = {
    .name = "max-distance",
    .value = "D",
    .help = "rays farther than D count as\nunoccluded (default: none)",
    .parse = parse_max_distance,
};

static int parse_fade_start(reference_request *rq, const char *value, gt_error *e)
{
    double d;
    if (parse_real_in("--fade-start", value, 1e-30, 1e30, &d, e) != 0)
        return -1;
    settings_of(rq)->fade_start = (float)d;
    return 0;
}

static const reference_option option_fade_start = {
    .name = "fade-start",
    .value = "F",
    .help = "with --max-distance D > F: an occluder\nat distance t counts with weight\n"
            "(D - t) / (D - F), clamped to [0, 1]\n(the GTAO talk's distance fade)",
    .parse = parse_fade_start,
};

static int parse_control_variate(reference_request *rq, const char *value, gt_error *e)
{
    if (ao_control_variate_parse(value, &settings_of(rq)->control_variate) != 0)
        return gt_error_set(e, "--control-variate", "'%s' is not none or heightfield", value);
    return 0;
}

static const reference_option option_control_variate = {
    .name = "control-variate",
    .value = "CV",
    .help = "none (default) or heightfield: each\nsample's height-field visibility g\n"
            "from the depth buffer's horizons as\na control variate, V - g + exact \\int g\n"
            "(ao.V and ao.Vuniform; unbiased)",
    .parse = parse_control_variate,
};

static void set_defaults(reference_request *rq)
{
    if (settings_of(rq))
        *settings_of(rq) = ao_render_settings_defaults();
}

int ao_quantity_write_settings(image *out, float max_distance, float fade_start, double target_stderr)
{
    if (fade_start > 0.0f && fade_start < max_distance)
        return reference_set_attributef(out, ATTR_SETTINGS, "max_distance=%.9g fade_start=%.9g target_stderr=%.9g",
                                        max_distance, fade_start, target_stderr);
    return reference_set_attributef(out, ATTR_SETTINGS, "max_distance=%.9g target_stderr=%.9g", max_distance,
                                    target_stderr);
}

/* ao's settings and, always, its sampling mode: merge compares it. */
static int write_settings(const reference_request *rq, image *out)
{
    ao_render_settings s = settings_or_defaults(rq);
    return ao_quantity_write_settings(out, s.max_distance, s.fade_start, rq->sampling.target_stderr) |
           image_set_attribute(out, ATTR_CONTROL_VARIATE, ao_control_variate_name(s.control_variate));
}

typedef struct {
    ao_settings settings;
    ao_control_variate_field field;
} ao_state;

static int prepare(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    ao_state *ao = calloc(1, sizeof *ao);
    if (!ao)
        return gt_error_set(e, pass->scene_spec, "out of memory");
    ao_render_settings s = settings_or_defaults(pass->req);
    ao->settings.max_distance = s.max_distance;
    ao->settings.fade_start = s.fade_start;
    if (s.control_variate == AO_CONTROL_VARIATE_HEIGHTFIELD) {
        int threads = pass->req->sampling.threads;
        if (ao_control_variate_build(&ao->field, pass->es, pass->gb, s.max_distance, threads) != 0) {
            free(ao);
            return gt_error_set(e, pass->scene_spec, "out of memory for the control variate's horizons");
        }
        ao->settings.control_variate = ao->field.pixels;
    }
    *state = ao;
    *it = ao_integrator(pass->es, &ao->settings);
    return 0;
}

static void release(void *state)
{
    ao_state *ao = state;
    ao_control_variate_free(&ao->field);
    free(ao);
}

/* Below this mean AO over the covered pixels nearly every ray is blocked:
 * inside a closed mesh (issue 41 met a mean of 0.0003), or an enclosure with
 * no --max-distance. The built-in scenes' views read 0.3 and above. */
#define AO_ENCLOSED_MEAN 0.01

/* The warning of a view whose AO says its camera is enclosed. */
static void warn_enclosed(const image *out, const char *scene_spec, const camera *cam)
{
    const float *ao = image_channel_data(out, CH_AO), *mask = image_channel_data(out, CH_MASK);
    double sum = 0;
    long covered = 0;
    for (long i = 0; ao && mask && i < (long)out->width * out->height; ++i)
        if (mask[i] > 0.5f)
            sum += ao[i], ++covered;
    if (covered > 0 && sum / (double)covered < AO_ENCLOSED_MEAN)
        gt_warn(scene_spec, "mean AO %.4f over the %ld pixels the camera sees: nearly every ray is blocked; is the "
                "camera (at %g, %g, %g) inside geometry?", sum / (double)covered, covered, cam->position.x,
                cam->position.y, cam->position.z);
}

const reference_quantity_descriptor reference_quantity_ao = {
    .name = "ao",
    .help = "the G-buffer plus ao.V (cosine AO), ao.Vuniform (uniform AO),\n"
            "bent.X/Y/Z (bent normal), each with .stderr and the exact\n"
            "accumulators (.sum, .sumeven, .peak, .m1_*, .m2_*) that 'gtlab merge'\n"
            "combines",
    .options = (const reference_option *const[]){&option_max_distance, &option_fade_start,
                                                  &option_control_variate, NULL},
    .settings_size = sizeof(ao_render_settings),
    .set_defaults = set_defaults,
    .prepare = prepare,
    .release = release,
    .write_settings = write_settings,
    .warn_about = warn_enclosed,
};
