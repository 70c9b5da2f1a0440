#include "gpu/spirv_bindings.h"

#include <string.h>

/* Opcodes, decorations and storage classes of the SPIR-V specification. */
enum { SPV_MAGIC = 0x07230203u, OP_TYPE_IMAGE = 25, OP_TYPE_SAMPLER = 26, OP_TYPE_SAMPLED_IMAGE = 27,
       OP_TYPE_POINTER = 32, OP_VARIABLE = 59, OP_DECORATE = 71 };
enum { DEC_BUFFER_BLOCK = 3, DEC_BINDING = 33, DEC_DESCRIPTOR_SET = 34 };
enum { SC_UNIFORM_CONSTANT = 0, SC_UNIFORM = 2, SC_STORAGE_BUFFER = 12 };

/* What one pass over the instructions gathers, by result id. */
typedef struct {
    uint32_t id[GPU_MAX_DECLARED], set[GPU_MAX_DECLARED], binding[GPU_MAX_DECLARED];
    int count;
} decorated;

static int find(const decorated *d, uint32_t id)
{
    for (int i = 0; i < d->count; ++i)
        if (d->id[i] == id)
            return i;
    return -1;
}

/* OpDecorate id Binding n / DescriptorSet n. */
static void note_decoration(decorated *d, const uint32_t *op)
{
    if (op[2] != DEC_BINDING && op[2] != DEC_DESCRIPTOR_SET)
        return;
    int i = find(d, op[1]);
    if (i < 0 && d->count < GPU_MAX_DECLARED) {
        i = d->count++;
        d->id[i] = op[1], d->set[i] = 0, d->binding[i] = 0;
    }
    if (i >= 0)
        *(op[2] == DEC_BINDING ? &d->binding[i] : &d->set[i]) = op[3];
}

/* The kind of a UniformConstant variable of type `type`: an image with
 * Sampled = 1 (OpTypeImage's seventh word), a sampler or a sampled image. */
static gpu_declared_kind opaque_kind(const uint32_t *words, size_t count, uint32_t type)
{
    for (size_t at = 5; at < count;) {
        uint32_t n = words[at] >> 16, op = words[at] & 0xffffu;
        if (n >= 2 && at + 1 < count && words[at + 1] == type && op >= OP_TYPE_IMAGE && op <= OP_TYPE_SAMPLED_IMAGE) {
            if (op == OP_TYPE_SAMPLER)
                return GPU_DECLARED_SAMPLER;
            if (op == OP_TYPE_SAMPLED_IMAGE)
                return GPU_DECLARED_COMBINED_IMAGE_SAMPLER;
            return n >= 9 && at + 7 < count && words[at + 7] == 1 ? GPU_DECLARED_SAMPLED_IMAGE : GPU_DECLARED_OTHER;
        }
        at += n ? n : count;
    }
    return GPU_DECLARED_OTHER;
}

/* The kind of a variable of storage class sc pointing at type `pointee`. */
static gpu_declared_kind kind_of(const uint32_t *words, size_t count, uint32_t sc, uint32_t pointee)
{
    if (sc == SC_STORAGE_BUFFER)
        return GPU_DECLARED_STORAGE;
    if (sc == SC_UNIFORM_CONSTANT)
        return opaque_kind(words, count, pointee);
    if (sc != SC_UNIFORM)
        return GPU_DECLARED_OTHER;
    for (size_t at = 5; at < count;) { /* a BufferBlock struct is a storage buffer (SPIR-V 1.0 style) */
        uint32_t n = words[at] >> 16, op = words[at] & 0xffffu;
        if (op == OP_DECORATE && n >= 3 && at + 2 < count && words[at + 1] == pointee && words[at + 2] == DEC_BUFFER_BLOCK)
            return GPU_DECLARED_STORAGE;
        at += n ? n : count;
    }
    return GPU_DECLARED_UNIFORM;
}

/* The pointee of pointer type `type`, or 0. */
static uint32_t pointee_of(const uint32_t *words, size_t count, uint32_t type)
{
    for (size_t at = 5; at < count;) {
        uint32_t n = words[at] >> 16, op = words[at] & 0xffffu;
        if (op == OP_TYPE_POINTER && n == 4 && at + 3 < count && words[at + 1] == type)
            return words[at + 3];
        at += n ? n : count;
    }
    return 0;
}

int gpu_spirv_bindings(const uint32_t *words, size_t count, gpu_declared_binding *out)
{
    if (count < 5 || words[0] != SPV_MAGIC)
        return -1;
    decorated d;
    memset(&d, 0, sizeof d);
    for (size_t at = 5; at < count;) {
        uint32_t n = words[at] >> 16;
        if (n == 0 || at + n > count)
            return -1;
        if ((words[at] & 0xffffu) == OP_DECORATE && n >= 4)
            note_decoration(&d, words + at);
        at += n;
    }
    int found = 0;
    for (size_t at = 5; at < count; at += words[at] >> 16) {
        const uint32_t *op = words + at;
        int i = (op[0] & 0xffffu) == OP_VARIABLE && (op[0] >> 16) >= 4 ? find(&d, op[2]) : -1;
        if (i >= 0)
            out[found++] = (gpu_declared_binding){d.set[i], d.binding[i],
                                                  kind_of(words, count, op[3], pointee_of(words, count, op[1]))};
    }
    return found;
}
