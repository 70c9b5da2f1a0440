/* The registry of render quantities (cli/render_quantities.h, generated from
 * the techniques' QUANTITIES; raytracer/reference_quantity.h's look-ups):
 * every descriptor is complete and found by its name, in the order of
 * `gtlab render --help`; every option belongs to exactly the quantities that
 * list an option of its name (and is refused by the others with the message
 * `gtlab render` prints), objects sharing a name agree, and the options parse
 * into the request's fields or the quantity's own settings. */
#include <stdlib.h>
#include <string.h>

#include "cli/render_quantities.h"
#include "tests/check.h"
#include "environment/environment_light.h"
#include "ao/ao_quantity.h"
#include "ao/heightfield_ao_integrator.h"
#include "multibounce/multibounce_quantity.h"
#include "raytracer/reference_render.h"
#include "specular_occlusion/specular_occlusion_quantity.h"
#include "sphere_light/sphere_light_quantity.h"

enum { MAX_OPTIONS = 64 };

#define R (render_quantities())

static int nonempty(const char *text)
{
    return text && text[0] != '\0';
}

static const reference_option *option_named(const char *name)
{
    for (int i = 0; i < reference_option_count(R); ++i)
        if (strcmp(reference_option_at(R, i)->name, name) == 0)
            return reference_option_at(R, i);
    return NULL;
}

static int option_index(const reference_option *option)
{
    for (int i = 0; i < reference_option_count(R); ++i)
        if (strcmp(reference_option_at(R, i)->name, option->name) == 0)
            return i;
    return -1;
}

/* Applies the options named in pairs (name, value, name, value, ..., NULL)
 * to a fresh request of quantity q; returns apply's result, e its message. */
static int apply(reference_request *rq, reference_quantity q, gt_error *e, const char *const *pairs)
{
    const char *values[MAX_OPTIONS] = {0};
    static reference_settings *settings; /* the last request's, as verb_render's */
    free(settings);
    memset(rq, 0, sizeof *rq);
    rq->quantity = q;
    rq->settings = settings = reference_settings_new(q);
    CHECK_MSG(!q->settings_size || settings, "%s", q->name);
    if (q->set_defaults)
        q->set_defaults(rq);
    for (; pairs[0]; pairs += 2) {
        int i = option_index(option_named(pairs[0]));
        CHECK_MSG(i >= 0, "no option --%s", pairs[0]);
        if (i >= 0)
            values[i] = pairs[1];
    }
    e->message[0] = '\0';
    return reference_options_apply(R, rq, values, "render", e);
}

static void test_descriptors(void)
{
    int count = reference_quantity_count(R);
    CHECK(count >= 6);
    CHECK(reference_quantity_at(R, -1) == NULL && reference_quantity_at(R, count) == NULL);
    for (int i = 0; i < count; ++i) {
        reference_quantity q = reference_quantity_at(R, i), parsed = NULL;
        CHECK(q != NULL && nonempty(q->name) && nonempty(q->help));
        CHECK_MSG(reference_quantity_parse(R, q->name, &parsed) == 0 && parsed == q, "%s", q->name);
        CHECK(reference_quantity_find(R, q->name) == q && strcmp(reference_quantity_name(q), q->name) == 0);
        for (int j = 0; j < i; ++j)
            CHECK_MSG(strcmp(reference_quantity_at(R, j)->name, q->name) != 0, "%s registered twice", q->name);
        /* A sampled quantity writes its settings to the header. */
        CHECK_MSG(!q->prepare || q->write_settings, "%s", q->name);
    }
    reference_quantity q = QUANTITY_AO;
    CHECK(reference_quantity_parse(R, "smoke", &q) == -1 && q == QUANTITY_AO);
    CHECK(strcmp(reference_quantity_name(NULL), "unknown") == 0);
    CHECK(reference_quantity_find(R, "multibounce") == QUANTITY_MULTIBOUNCE);
    CHECK(reference_quantity_find(R, "heightfield-ao") == QUANTITY_HEIGHTFIELD_AO);
    CHECK(reference_quantity_find(R, "specular-occlusion") == QUANTITY_SPECULAR_OCCLUSION);
    CHECK(reference_quantity_find(R, "sphere-light") == QUANTITY_SPHERE_LIGHT);
    CHECK(QUANTITY_GBUFFER->prepare == NULL && QUANTITY_GBUFFER->options == NULL);
    char names[512];
    reference_quantity_names(R, names, sizeof names);
    CHECK_MSG(strcmp(names, "gbuffer, ao, multibounce, heightfield-ao, heightfield-multibounce, specular-occlusion, "
                            "sphere-light, fog, volumetric-light, env-diffuse or env-specular") == 0,
              "%s", names);
}

/* Every option listed by a quantity is enumerated once; names are unique. */
static void test_option_enumeration(void)
{
    int count = reference_option_count(R);
    CHECK(count > 0 && count <= MAX_OPTIONS);
    for (int i = 0; i < count; ++i) {
        const reference_option *o = reference_option_at(R, i);
        CHECK(nonempty(o->name) && nonempty(o->help) && o->parse != NULL);
        CHECK_MSG(!o->hint || o->required, "--%s: a hint without required", o->name);
        for (int j = 0; j < i; ++j)
            CHECK_MSG(strcmp(reference_option_at(R, j)->name, o->name) != 0, "--%s twice", o->name);
    }
    for (int i = 0; i < reference_quantity_count(R); ++i)
        for (const reference_option *const *o = reference_quantity_at(R, i)->options; o && *o; ++o)
            CHECK_MSG(option_index(*o) >= 0, "--%s of %s not enumerated", (*o)->name, reference_quantity_at(R, i)->name);
}

/* Objects of one name are one option: the same placeholder and `required`;
 * the help joins the distinct objects' (specular-occlusion's --environment,
 * then env-*'s). */
static void test_shared_names(void)
{
    for (int i = 0; i < reference_quantity_count(R); ++i)
        for (const reference_option *const *o = reference_quantity_at(R, i)->options; o && *o; ++o) {
            const reference_option *first = reference_option_at(R, option_index(*o));
            CHECK_MSG((first->value == NULL) == ((*o)->value == NULL) &&
                          (!first->value || strcmp(first->value, (*o)->value) == 0) &&
                          first->required == (*o)->required,
                      "--%s of %s disagrees with its first owner's", (*o)->name, reference_quantity_at(R, i)->name);
        }
    const reference_option *environment = option_named("environment");
    reference_quantity so = reference_quantity_find(R, "specular-occlusion");
    reference_quantity diffuse = reference_quantity_find(R, "env-diffuse");
    reference_quantity specular = reference_quantity_find(R, "env-specular");
    CHECK(reference_quantity_option(so, environment) != reference_quantity_option(diffuse, environment));
    CHECK(reference_quantity_option(diffuse, environment) == reference_quantity_option(specular, environment));
    char help[1024], expected[1024];
    reference_option_help(R, environment, help, sizeof help);
    snprintf(expected, sizeof expected, "%s\n%s", reference_quantity_option(so, environment)->help,
             reference_quantity_option(diffuse, environment)->help);
    CHECK_MSG(strcmp(help, expected) == 0, "%s", help);
    reference_option_help(R, option_named("max-distance"), help, sizeof help);
    CHECK(strcmp(help, option_named("max-distance")->help) == 0);
    /* env-diffuse's --albedo adds its line to multibounce's help; its
     * --bounces and env-specular's --roughness have none to add. */
    reference_quantity multibounce = reference_quantity_find(R, "multibounce");
    const reference_option *albedo = option_named("albedo");
    CHECK(reference_quantity_option(multibounce, albedo) != reference_quantity_option(diffuse, albedo));
    reference_option_help(R, albedo, help, sizeof help);
    snprintf(expected, sizeof expected, "%s\n%s", reference_quantity_option(multibounce, albedo)->help,
             reference_quantity_option(diffuse, albedo)->help);
    CHECK_MSG(strcmp(help, expected) == 0, "%s", help);
    CHECK(reference_quantity_option(diffuse, option_named("bounces"))->help == NULL);
    reference_option_help(R, option_named("bounces"), help, sizeof help);
    CHECK(strcmp(help, reference_quantity_option(multibounce, option_named("bounces"))->help) == 0);
    reference_option_help(R, option_named("roughness"), help, sizeof help);
    CHECK(strcmp(help, reference_quantity_option(so, option_named("roughness"))->help) == 0);
}

/* Each option is refused by exactly the quantities that do not list it, with
 * the message naming those that do. */
static void test_option_ownership(void)
{
    for (int i = 0; i < reference_option_count(R); ++i) {
        const reference_option *o = reference_option_at(R, i);
        char owners[256], expected[512];
        reference_option_owners(R, o, " and ", owners, sizeof owners);
        snprintf(expected, sizeof expected, "--%s: applies to %s only", o->name, owners);
        int owner_count = 0;
        for (int k = 0; k < reference_quantity_count(R); ++k) {
            reference_quantity q = reference_quantity_at(R, k);
            reference_request rq;
            gt_error e;
            const char *pairs[] = {o->name, o->value ? "x" : "", NULL};
            int rc = apply(&rq, q, &e, pairs);
            int refused = rc != 0 && strcmp(e.message, expected) == 0;
            owner_count += reference_quantity_lists(q, o);
            CHECK_MSG(refused == !reference_quantity_lists(q, o), "--%s with %s: %s", o->name, q->name, e.message);
            CHECK_MSG(!reference_quantity_lists(q, o) || strstr(owners, q->name), "%s", owners);
        }
        CHECK_MSG(owner_count >= 1, "--%s belongs to no quantity", o->name);
    }
    char owners[256];
    reference_option_owners(R, option_named("max-distance"), " and ", owners, sizeof owners);
    CHECK_MSG(strcmp(owners, "ao and heightfield-ao") == 0, "%s", owners);
    reference_option_owners(R, option_named("roughness"), ", ", owners, sizeof owners);
    CHECK_MSG(strcmp(owners, "specular-occlusion, env-specular") == 0, "%s", owners);
    reference_option_owners(R, option_named("environment"), " and ", owners, sizeof owners);
    CHECK_MSG(strcmp(owners, "specular-occlusion, env-diffuse and env-specular") == 0, "%s", owners);
}

/* The messages tests/cli checks, and the values reaching the request. */
static void test_apply(void)
{
    reference_request rq;
    gt_error e;
    CHECK(apply(&rq, QUANTITY_MULTIBOUNCE, &e, (const char *[]){"bounces", "3", NULL}) != 0);
    CHECK_MSG(strcmp(e.message, "render: multibounce needs --albedo (grey albedos such as 0.1,0.5,0.9, or 'scene')") == 0,
              "%s", e.message);
    CHECK(apply(&rq, QUANTITY_SPHERE_LIGHT, &e, (const char *[]){"light-position", "0,2,0", NULL}) != 0);
    CHECK_MSG(strcmp(e.message, "render: sphere-light needs --light-position and --light-radius") == 0, "%s",
              e.message);
    CHECK(apply(&rq, QUANTITY_SPECULAR_OCCLUSION, &e, (const char *[]){"roughness", "1.5", NULL}) != 0);
    CHECK_MSG(strcmp(e.message, "--roughness: 1.5 is out of range [0, 1]") == 0, "%s", e.message);

    CHECK(apply(&rq, QUANTITY_MULTIBOUNCE, &e, (const char *[]){"albedo", "0.3,0.6", NULL}) == 0);
    const multibounce_settings *mb = multibounce_settings_of(&rq);
    CHECK(mb && mb->albedo_count == 2 && mb->bounces == 4 && !mb->scene_albedo);
    CHECK(apply(&rq, QUANTITY_HEIGHTFIELD_MULTIBOUNCE, &e,
                (const char *[]){"bounces", "inf", "albedo", "scene", NULL}) == 0);
    mb = multibounce_settings_of(&rq);
    CHECK(mb && mb->scene_albedo && mb->bounces == MULTIBOUNCE_UNLIMITED);
    CHECK(apply(&rq, QUANTITY_SPHERE_LIGHT, &e,
                (const char *[]){"light-position", "1,2,3", "light-radius", "0.5", "shadows", "", NULL}) == 0);
    const sphere_light_settings *light =
        &((const sphere_light_quantity_settings *)reference_settings_of(&rq, QUANTITY_SPHERE_LIGHT))->light;
    CHECK(light->position.y == 2.0f && light->radius == 0.5f);
    CHECK(light->radiance == 1.0f && light->shadows == 1);
    CHECK(apply(&rq, QUANTITY_AO, &e, (const char *[]){NULL}) == 0);
    const ao_render_settings *ao = (const ao_render_settings *)reference_settings_of(&rq, QUANTITY_AO);
    CHECK(ao && isinf(ao->max_distance) && ao->fade_start == 0.0f && ao->control_variate == AO_CONTROL_VARIATE_NONE);
    CHECK(apply(&rq, QUANTITY_AO, &e,
                (const char *[]){"max-distance", "2", "fade-start", "1", "control-variate", "heightfield", NULL}) == 0);
    ao = (const ao_render_settings *)reference_settings_of(&rq, QUANTITY_AO);
    CHECK(ao && ao->max_distance == 2.0f && ao->fade_start == 1.0f &&
          ao->control_variate == AO_CONTROL_VARIATE_HEIGHTFIELD);
    CHECK(apply(&rq, QUANTITY_HEIGHTFIELD_AO, &e, (const char *[]){"max-distance", "2.5", NULL}) == 0);
    const heightfield_ao_options *hf =
        (const heightfield_ao_options *)reference_settings_of(&rq, QUANTITY_HEIGHTFIELD_AO);
    CHECK(hf && hf->max_distance == 2.5f && isinf(hf->thickness));
    CHECK(apply(&rq, QUANTITY_HEIGHTFIELD_AO, &e, (const char *[]){"thickness", "0.25", NULL}) == 0);
    hf = (const heightfield_ao_options *)reference_settings_of(&rq, QUANTITY_HEIGHTFIELD_AO);
    CHECK(hf && hf->thickness == 0.25f && isinf(hf->max_distance));
    /* Settings made for another quantity are not reached as its own. */
    CHECK(reference_settings_of(&rq, QUANTITY_SPHERE_LIGHT) == NULL);
    CHECK(apply(&rq, QUANTITY_SPECULAR_OCCLUSION, &e, (const char *[]){"environment", "sky", NULL}) == 0);
    const specular_occlusion_render_settings *so =
        (const specular_occlusion_render_settings *)reference_settings_of(&rq, QUANTITY_SPECULAR_OCCLUSION);
    CHECK(so && so->environment == ENVIRONMENT_SKY && so->roughness < 0.0f);
    CHECK(apply(&rq, QUANTITY_SPECULAR_OCCLUSION, &e, (const char *[]){"roughness", "0.25", NULL}) == 0);
    so = (const specular_occlusion_render_settings *)reference_settings_of(&rq, QUANTITY_SPECULAR_OCCLUSION);
    CHECK(so && so->environment == ENVIRONMENT_WHITE && so->roughness == 0.25f);
    /* env-diffuse parses --environment, --albedo and --bounces with its own
     * objects, into its settings; env-specular --roughness. */
    CHECK(apply(&rq, reference_quantity_find(R, "env-diffuse"), &e,
                (const char *[]){"environment", "sun", "albedo", "0.5", NULL}) == 0);
    const environment_render_settings *env =
        (const environment_render_settings *)reference_settings_of(&rq, reference_quantity_find(R, "env-diffuse"));
    CHECK(env && strcmp(env->environment, "sun") == 0 && multibounce_settings_of(&rq) == NULL);
    CHECK(env->multibounce.albedo_count == 1 && env->multibounce.albedos[0] == 0.5f && env->multibounce.bounces == 4);
    CHECK(apply(&rq, reference_quantity_find(R, "env-specular"), &e, (const char *[]){"roughness", "0.75", NULL}) == 0);
    env = (const environment_render_settings *)reference_settings_of(&rq, reference_quantity_find(R, "env-specular"));
    CHECK(env && env->roughness == 0.75f && reference_settings_of(&rq, QUANTITY_SPECULAR_OCCLUSION) == NULL);
}

int main(void)
{
    test_descriptors();
    test_option_enumeration();
    test_option_ownership();
    test_shared_names();
    test_apply();
    return check_report("cli_render_quantities");
}
