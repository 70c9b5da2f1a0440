/* The analytic environment of the split-integral comparison (the GTSO part
 * of Jimenez et al. 2016, slides "Two Split" / "Three Split"): under a white
 * dome the two- and three-split approximations coincide, so comparing them
 * needs light that varies with direction, and varies in a way a reader can
 * reproduce. World up is +Y (glTF). For a unit direction w:
 *
 *   L_sky(w) = 0.2 + 0.8 max(0, w.y) + 5 exp(32 (w.s - 1))
 *
 * a ground/horizon floor of 0.2, a sky brightening towards the zenith, and a
 * sun-like lobe of peak 5 and width ~1/sqrt(32) rad (10 degrees) about
 * s = (cos 30° sin 35°, sin 30°, cos 30° cos 35°): 30 degrees up, turned 35
 * degrees from +Z towards +X. Smooth, positive, at most 6. */
#ifndef GTLAB_CORE_OPTICS_SKY_ENVIRONMENT_H
#define GTLAB_CORE_OPTICS_SKY_ENVIRONMENT_H

#include "core/vec3.h"

typedef enum { ENVIRONMENT_WHITE, ENVIRONMENT_SKY } environment_kind;

/* "white" / "sky" -> kind; -1 if unknown. */
int environment_parse(const char *name, environment_kind *kind);
const char *environment_name(environment_kind kind);

/* L_sky(w) above, w a unit world-space direction. */
double sky_radiance(vec3 w);

#endif
