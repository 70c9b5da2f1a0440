/* The shading languages gtlab writes functions in. Each generator puts the
 * text of a .inc (written once in the common subset of C, HLSL and GLSL and
 * compiled as C by gtlab itself) behind a few definitions of the language's
 * dialect. */
#ifndef GTLAB_REALTIME_SHADER_LANGUAGE_H
#define GTLAB_REALTIME_SHADER_LANGUAGE_H

typedef enum { SHADER_HLSL, SHADER_GLSL } shader_language;

#endif
