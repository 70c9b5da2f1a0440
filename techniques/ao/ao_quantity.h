/* The settings of `gtlab render ao` (ao_quantity.c), its own struct headed
 * by a reference_settings naming it (reference_quantity.h), and what ao
 * shares with heightfield-ao: the parse of --max-distance and the settings
 * header. A caller of reference_render points `.settings` at the header:
 *
 *   ao_render_settings ao = ao_render_settings_defaults();
 *   ao.max_distance = 2.0f;
 *   reference_request req = {.quantity = QUANTITY_AO, ..., .settings = &ao.header};
 *
 * A request without them (settings NULL) renders with the defaults. */
#ifndef GTLAB_AO_AO_QUANTITY_H
#define GTLAB_AO_AO_QUANTITY_H

#include "ao/ao_control_variate.h"
#include "raytracer/reference_render.h"

/* The two AO quantities (ao_quantity.c, heightfield_ao_quantity.c), by name
 * for callers: `.quantity = QUANTITY_AO`. */
extern const reference_quantity_descriptor reference_quantity_ao, reference_quantity_heightfield_ao;
#define QUANTITY_AO (&reference_quantity_ao)
#define QUANTITY_HEIGHTFIELD_AO (&reference_quantity_heightfield_ao)

typedef struct {
    reference_settings header; /* names reference_quantity_ao */
    float max_distance;        /* rays farther count as unoccluded; INFINITY: none */
    float fade_start;          /* occlusion fades linearly to 0 from here to max_distance
                                  (techniques/ao/ao_integrator.h); 0: a hard cutoff */
    ao_control_variate control_variate; /* none (plain sampling) or heightfield */
} ao_render_settings;

/* No distance limit, no fade, plain sampling: `gtlab render ao`'s defaults. */
ao_render_settings ao_render_settings_defaults(void);

/* The value of --max-distance (ao's and heightfield-ao's, each parsing it
 * into its own settings): a distance > 0 (errors name "--max-distance").
 * Returns 0, or -1 with e set. */
int ao_parse_max_distance(const char *value, float *max_distance, gt_error *e);

/* gtlab.settings "max_distance=D target_stderr=E", with " fade_start=F"
 * after D when 0 < F < D (ao's; heightfield-ao's without a thickness). */
int ao_quantity_write_settings(image *out, float max_distance, float fade_start, double target_stderr);

#endif
