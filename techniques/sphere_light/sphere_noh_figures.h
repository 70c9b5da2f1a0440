/* The plots of the GetNoHSquared sweep (sphere_light/sphere_light_study.h,
 * sphere_noh_study), shared by `gtlab check sphere-noh` and the sphere-light
 * stage of `gtlab all`. */
#ifndef GTLAB_SPHERE_LIGHT_SPHERE_NOH_FIGURES_H
#define GTLAB_SPHERE_LIGHT_SPHERE_NOH_FIGURES_H

#include "core/error.h"

/* From DIR/sphere_noh_map.csv and DIR/sphere_noh_by_nv.csv:
 * DIR/sphere_noh_map.png (where one Newton step helps or hurts over n.v and
 * the light's elevation) and DIR/sphere_noh_error.png (mean shortfall
 * against n.v). */
int sphere_noh_plots(const char *dir, gt_error *e);

#endif
