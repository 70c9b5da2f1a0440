/* Decima's sphere light for an engine: GetNoHSquared (gtlab's Newton step)
 * and EvaluateSphericalAreaGGX with given constants, as HLSL or GLSL. The
 * functions are sphere_light/sphere_light.inc itself, the text sphere_light/sphere_light.c
 * compiles as C, behind a few definitions of the language's dialect: no
 * formula is written for the shaders alone but the visibility and Fresnel
 * that C takes from core/ (checked against core/ by the tests). */
#ifndef GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_SHADER_H
#define GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_SHADER_H

#include "realtime/shader_language.h"
#include "sphere_light/sphere_light.h"

/* The text of sphere_light/sphere_light.inc, embedded by the build. */
extern const char sphere_light_inc_text[];

/* The shader source (malloc'd; NULL if out of memory): a header comment
 * naming `generator`, the constants k, the dialect and the functions. */
char *sphere_light_shader_source(shader_language language, const decima_sphere_constants *k, const char *generator);

#endif
