/* A reference quantity of `gtlab render` as data (docs/render-quantities.md).
 *
 * Each quantity is one descriptor, defined in <quantity>_quantity.c beside
 * its integrator (a technique's REFERENCE part, or raytracer/ for those still
 * shared). A registry lists them: the raytracer defines the type and its
 * look-ups below but not the list, which is generated from the techniques'
 * folders (cli/render_quantities.h) and handed to whatever looks a quantity
 * up by name (gtlab render, gtlab merge). reference_render() builds the Embree
 * scene and the G-buffer, then calls the descriptor: `prepare` builds the
 * integrator over the G-buffer, the shared sampling loop (render_loop.h)
 * runs it, `finish` derives channels from the accumulated sums, and
 * `write_settings` writes the quantity's header attributes. `gtlab render`
 * builds its command line from the descriptors: the help, one long option
 * per reference_option, and the refusal of another quantity's options.
 *
 * A quantity is named by the address of its descriptor (reference_quantity is
 * a pointer): callers compare `req->quantity == QUANTITY_AO`. */
#ifndef GTLAB_RAYTRACER_REFERENCE_QUANTITY_H
#define GTLAB_RAYTRACER_REFERENCE_QUANTITY_H

#include <stddef.h>

#include "core/error.h"
#include "core/image.h"
#include "raytracer/embree_scene.h"
#include "raytracer/gbuffer.h"
#include "raytracer/render_loop.h"
#include "scene/scene.h"

struct reference_request; /* raytracer/reference_render.h */
struct reference_quantity_descriptor;

/* The head of every quantity's own settings struct, as its first member
 * (`typedef struct { reference_settings header; float max_distance, thickness; }
 * heightfield_ao_options;`): it names the quantity the settings are for. A
 * request carries them as a reference_settings pointer and a quantity
 * reaches its own through reference_settings_of, which refuses another
 * quantity's: settings given to the wrong quantity are "no settings", never
 * memory read as the wrong struct. */
typedef struct reference_settings {
    const struct reference_quantity_descriptor *quantity;
} reference_settings;

/* One command-line option of one or more quantities ("--max-distance D").
 * An option is its name: quantities share one by listing the same object
 * or objects of the same name, value placeholder and `required`, each
 * parsing into its own quantity's settings (ao and heightfield-ao each
 * their --max-distance; specular-occlusion and env-* their --environment
 * and --roughness: a quantity never calls another technique's code). `gtlab
 * render` shows it once, its help the distinct objects' helps in registry
 * order, parses it with the rendered quantity's object and refuses it with
 * any other quantity ("--max-distance: applies to ao and heightfield-ao
 * only"). */
typedef struct reference_option {
    const char *name;     /* the long option without "--" */
    const char *value;    /* the value's placeholder in the help ("D"), or NULL: a flag */
    int required;         /* 1: the quantities listing it need it */
    const char *hint;     /* with `required`: what to give, appended to the "needs" error, or NULL */
    const char *help;     /* after "<quantities>: ", lines separated by '\n'; NULL: another object's of its name says it all */
    /* Parses the value (NULL for a flag) into the request (its sampling, or
     * the quantity's settings, reference_settings_of). Errors name "--<name>". */
    int (*parse)(struct reference_request *rq, const char *value, gt_error *e);
} reference_option;

/* What prepare builds on: the scene, its G-buffer and the request. */
typedef struct reference_pass {
    const scene *scene;
    const char *scene_spec; /* for errors */
    const camera *cam;
    const embree_scene *es;
    const gbuffer *gb;
    const struct reference_request *req;
} reference_pass;

typedef struct reference_quantity_descriptor {
    const char *name; /* the QUANTITY argument and the header's gtlab.quantity */
    const char *help; /* the channels it writes, for --help; lines separated by '\n' */
    const reference_option *const *options; /* its own options, NULL-terminated; NULL: none */
    /* The size of the quantity's own settings struct (which begins with its
     * reference_settings header): `gtlab render` allocates it zeroed, its
     * header naming the quantity (reference_settings_new), as rq->settings
     * before set_defaults and the options run (0: none). */
    size_t settings_size;
    /* The defaults of its settings before the options apply; NULL: zeros. */
    void (*set_defaults)(struct reference_request *rq);
    /* Validates the settings and builds the integrator over the G-buffer;
     * *state (freed by release) holds what the integrator points at.
     * NULL: the quantity is the G-buffer alone (no sampling, no spp/seed/
     * sample-block header). */
    int (*prepare)(const reference_pass *pass, void **state, integrator *it, gt_error *e);
    void (*release)(void *state);
    /* Channels derived from the accumulated ones, after rendering and after
     * `gtlab merge` (specular_occlusion_write_ratios); NULL: none. Returns 0,
     * or -1 when out of memory. */
    int (*finish)(image *out);
    /* gtlab.settings (for people) and the typed attributes of its settings;
     * NULL: none. Returns 0, or -1 when out of memory. */
    int (*write_settings)(const struct reference_request *rq, image *out);
    /* After a render (in the process that writes it): a warning on stderr
     * when the image says the setting is likely not what was meant (the AO
     * quantity: nearly every ray blocked, a camera inside geometry); NULL:
     * none. */
    void (*warn_about)(const image *out, const char *scene_spec, const camera *cam);
} reference_quantity_descriptor;

typedef const reference_quantity_descriptor *reference_quantity;

/* ---- A registry (raytracer/reference_registry.c) ------------------------ */
/* The quantities a program knows, in the order of `gtlab render --help` and
 * of the names in its messages. `gtlab` has one, generated from the
 * technique list (cli/render_quantities.h); a program that needs only some
 * quantities lists them (REFERENCE_REGISTRY_OF). */
typedef struct reference_registry {
    const reference_quantity *quantities;
    int count;
} reference_registry;

/* A registry of the quantities given, in that order:
 * `reference_merge(&REFERENCE_REGISTRY_OF(QUANTITY_AO), ...)`. */
#define REFERENCE_REGISTRY_OF(...)                                                                                 \
    ((const reference_registry){(const reference_quantity[]){__VA_ARGS__},                                         \
                                (int)(sizeof((const reference_quantity[]){__VA_ARGS__}) / sizeof(reference_quantity))})

int reference_quantity_count(const reference_registry *r);
/* 0 <= index < count, in registry order; NULL outside. */
reference_quantity reference_quantity_at(const reference_registry *r, int index);
/* The quantity of that name, or NULL. */
reference_quantity reference_quantity_find(const reference_registry *r, const char *name);
/* name -> quantity; -1 if unknown (q unchanged). */
int reference_quantity_parse(const reference_registry *r, const char *name, reference_quantity *q);
const char *reference_quantity_name(reference_quantity q); /* "unknown" for NULL */
/* "gbuffer, ao, ... or sphere-light": every name, for messages. */
void reference_quantity_names(const reference_registry *r, char *text, size_t size);
/* 1 if q lists an option of that option's name. */
int reference_quantity_lists(reference_quantity q, const reference_option *option);
/* q's own object of the option's name, or NULL. */
const reference_option *reference_quantity_option(reference_quantity q, const reference_option *option);

/* Every option of every quantity once (by name), in registry order: its
 * first owner's object (the command line's quantity options; values[] below
 * is indexed the same way). */
int reference_option_count(const reference_registry *r);
const reference_option *reference_option_at(const reference_registry *r, int index);
/* The quantities that list the option, the last joined by last_joint:
 * "ao and heightfield-ao" (" and "), "ao, heightfield-ao" (", "). */
void reference_option_owners(const reference_registry *r, const reference_option *option, const char *last_joint,
                             char *text, size_t size);
/* The option's help: the helps of the distinct objects of its name, in
 * registry order, one after the other on new lines. */
void reference_option_help(const reference_registry *r, const reference_option *option, char *text, size_t size);

/* Applies command-line values to a request whose quantity is set:
 * values[i] is the value of reference_option_at(r, i) ("" for a flag), or
 * NULL when not given. Refuses an option the quantity does not list ("--x:
 * applies to ... only"), then a missing required option ("<subject>: q needs
 * --a and --b"), then parses its options in the quantity's order, each with
 * its own object. */
int reference_options_apply(const reference_registry *r, struct reference_request *rq, const char *const *values,
                            const char *subject, gt_error *e);

/* ---- Settings ------------------------------------------------------------ */
/* q->settings_size zeroed bytes (free() them) whose header names q; NULL when
 * q keeps no settings of its own or out of memory. */
reference_settings *reference_settings_new(reference_quantity q);
/* rq's settings when their header names q, else NULL (none given, or another
 * quantity's). A quantity casts the result to its own struct, whose first
 * member the header is. */
reference_settings *reference_settings_of(const struct reference_request *rq, reference_quantity q);

/* ---- Helpers for the descriptors --------------------------------------- */
/* Appends item i of n to the list in text: "a", ", b", ..., "<last_joint>z"
 * (last_joint " and " or " or "). */
void reference_append_listed(char *text, size_t size, int i, int n, const char *last_joint, const char *item);
/* image_set_attribute with printf formatting (at most 1023 characters). */
int reference_set_attributef(image *img, const char *key, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* A roughness setting (core/roughness_setting.h) in the header: gtlab.roughness
 * when it is one roughness for every surface (absent: the materials'), and
 * its text for gtlab.settings ("material" or the number) into text. Returns
 * 0, or -1 when out of memory. */
int reference_write_roughness(image *out, float roughness, char *text, size_t size);
/* The value of --roughness, one perceptual roughness in [0, 1] for every
 * surface (errors name "--roughness"). Returns 0, or -1 with e set. */
int reference_parse_roughness(const char *value, float *roughness, gt_error *e);

#endif
