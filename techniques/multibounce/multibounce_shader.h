/* GTAOMultiBounce for an engine: fitted models of multibounce/multibounce.h as a
 * C header or HLSL/GLSL functions. The formula is multibounce/multibounce.inc
 * itself, the text multibounce/multibounce.c compiles as C, behind a few
 * definitions of the language's dialect; a function only passes its
 * coefficients to it, printed from the doubles as float literals ("%.9g",
 * enough to give back the float nearest each double). */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_SHADER_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_SHADER_H

#include "multibounce/multibounce.h"
#include "realtime/shader_language.h"

/* The text of multibounce/multibounce.inc, embedded by the build. */
extern const char multibounce_inc_text[];

/* One generated function. */
typedef struct {
    const char *name;        /* e.g. "GTAOMultiBounce", "gtlab_multibounce_linear" */
    const char *comment;     /* the line above it, without comment delimiters */
    multibounce_model model; /* degree 1 or 2 (degree 0 is written as a quadratic with zero terms) */
} multibounce_shader_function;

/* HLSL or GLSL (malloc'd; NULL if out of memory): `preamble` verbatim (its
 * own comment lines), the dialect, the .inc, then for each function
 *   float3 name(float visibility, float3 albedo)   (vec3 in GLSL),
 * V'_d per colour channel. */
char *multibounce_shader_source(shader_language language, const char *preamble,
                                const multibounce_shader_function *functions, int count);

/* A C header (malloc'd; NULL if out of memory): `preamble`, the include
 * guard `guard`, the dialect (float), the .inc, then for each function
 *   static inline float name(float visibility, float albedo). */
char *multibounce_c_header_source(const char *preamble, const char *guard,
                                  const multibounce_shader_function *functions, int count);

#endif
