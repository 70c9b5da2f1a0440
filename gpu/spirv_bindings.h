/* The resources a compiled shader declares, read from its SPIR-V (the SPIR-V
 * specification, 2.3 "Physical Layout" and 3.20 "Decoration"): which
 * (descriptor set, binding) pairs it uses and whether each is a uniform
 * block, a storage buffer, a sampled image, a sampler or the two combined. Read only, to refuse a shader whose bindings
 * are not the contract's with one clear line instead of a driver crash;
 * gtlab writes no SPIR-V. */
#ifndef GTLAB_GPU_SPIRV_BINDINGS_H
#define GTLAB_GPU_SPIRV_BINDINGS_H

#include <stddef.h>
#include <stdint.h>

#define GPU_MAX_DECLARED 64

/* OpTypeImage with Sampled = 1 (HLSL Texture2D), OpTypeSampler (HLSL
 * SamplerState), OpTypeSampledImage (GLSL sampler2D); OTHER: anything else
 * (a storage image, a texel buffer, ...). */
typedef enum {
    GPU_DECLARED_UNIFORM,
    GPU_DECLARED_STORAGE,
    GPU_DECLARED_SAMPLED_IMAGE,
    GPU_DECLARED_SAMPLER,
    GPU_DECLARED_COMBINED_IMAGE_SAMPLER,
    GPU_DECLARED_OTHER
} gpu_declared_kind;

typedef struct {
    uint32_t set, binding;
    gpu_declared_kind kind;
} gpu_declared_binding;

/* The bindings of words[0 .. count-1] into out (at most GPU_MAX_DECLARED).
 * Returns how many, or -1 when the words are not a SPIR-V module. */
int gpu_spirv_bindings(const uint32_t *words, size_t count, gpu_declared_binding *out);

#endif
