/* What the ao quantity shares with heightfield-ao (ao_quantity.c): the
 * --max-distance option and the settings header. */
#ifndef GTLAB_RAYTRACER_AO_QUANTITY_H
#define GTLAB_RAYTRACER_AO_QUANTITY_H

#include "raytracer/reference_render.h"

extern const reference_option reference_option_max_distance;

/* rq->max_distance = INFINITY (no limit). */
void ao_quantity_set_defaults(reference_request *rq);
/* gtlab.settings "max_distance=D target_stderr=E". */
int ao_quantity_write_settings(const reference_request *rq, image *out);

#endif
