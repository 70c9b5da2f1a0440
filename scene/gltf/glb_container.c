/* GLB container splitting (glb_container.h). Beyond the specification, the
 * BIN chunk is held to what tinygltf 2.7.0 requires of it (at least 4 bytes,
 * a multiple of 4), so that a file accepted here is one tinygltf reads. */
#include "scene/gltf/glb_container.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define GLB_HEADER 12u
#define CHUNK_HEADER 8u
#define CHUNK_JSON 0x4E4F534Au /* "JSON" read as a little-endian uint32 */
#define CHUNK_BIN 0x004E4942u  /* "BIN\0" */

static uint32_t read_u32le(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

int glb_has_magic(const unsigned char *bytes, size_t size) { return size >= 4 && memcmp(bytes, "glTF", 4) == 0; }

/* The chunk header at `offset`: its data must end within `length`. */
static int read_chunk(const unsigned char *bytes, uint64_t offset, uint64_t length, const char *name,
                      const char *what, uint32_t *type, uint64_t *data_length, gt_error *e)
{
    if (offset + CHUNK_HEADER > length)
        return gt_error_set(e, what, "GLB %s chunk header lies past the end of the file (truncated?)", name);
    *data_length = read_u32le(bytes + offset);
    *type = read_u32le(bytes + offset + 4);
    if (offset + CHUNK_HEADER + *data_length > length)
        return gt_error_set(e, what, "GLB %s chunk of %llu bytes runs past the end of the file (truncated?)", name,
                            (unsigned long long)*data_length);
    return 0;
}

static int read_header(const unsigned char *bytes, size_t size, const char *what, uint64_t *length, gt_error *e)
{
    if (!glb_has_magic(bytes, size))
        return gt_error_set(e, what, "not a binary glTF file (no \"glTF\" magic)");
    if (size < GLB_HEADER)
        return gt_error_set(e, what, "GLB header is cut short (%zu bytes; truncated?)", size);
    const uint32_t version = read_u32le(bytes + 4);
    *length = read_u32le(bytes + 8);
    if (version != 2)
        return gt_error_set(e, what, "GLB version %u is not supported: gtlab reads binary glTF 2.0 (GLB version 2)", version);
    if (*length > size)
        return gt_error_set(e, what, "GLB header gives a length of %llu bytes but the file has %zu (truncated?)",
                            (unsigned long long)*length, size);
    return 0;
}

int glb_split(const unsigned char *bytes, size_t size, const char *what, glb_chunks *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    uint64_t length = 0, json_length = 0, bin_length = 0;
    uint32_t type = 0;
    if (read_header(bytes, size, what, &length, e) != 0 ||
        read_chunk(bytes, GLB_HEADER, length, "JSON", what, &type, &json_length, e) != 0)
        return -1;
    if (type != CHUNK_JSON || json_length == 0)
        return gt_error_set(e, what, "GLB file does not start with a JSON chunk");
    out->json = bytes + GLB_HEADER + CHUNK_HEADER;
    out->json_length = (size_t)json_length;
    const uint64_t bin_offset = GLB_HEADER + CHUNK_HEADER + json_length;
    if (bin_offset == length)
        return 0;
    if (read_chunk(bytes, bin_offset, length, "BIN", what, &type, &bin_length, e) != 0)
        return -1;
    if (type != CHUNK_BIN)
        return gt_error_set(e, what, "GLB second chunk is not BIN");
    if (bin_length < 4 || bin_length % 4 != 0)
        return gt_error_set(e, what, "GLB BIN chunk of %llu bytes is not a positive multiple of 4",
                            (unsigned long long)bin_length);
    out->bin = bytes + bin_offset + CHUNK_HEADER;
    out->bin_length = (size_t)bin_length;
    return 0;
}

static void write_u32le(unsigned char *p, uint32_t v)
{
    for (int i = 0; i < 4; ++i)
        p[i] = (unsigned char)(v >> (8 * i));
}

/* One chunk at p: header, data, then padding to 4 bytes with `pad`. */
static size_t write_chunk(unsigned char *p, uint32_t type, const unsigned char *data, size_t length, unsigned char pad)
{
    const size_t padded = (length + 3) & ~(size_t)3;
    write_u32le(p, (uint32_t)padded);
    write_u32le(p + 4, type);
    memcpy(p + CHUNK_HEADER, data, length);
    memset(p + CHUNK_HEADER + length, pad, padded - length);
    return CHUNK_HEADER + padded;
}

unsigned char *glb_join(const glb_chunks *chunks, size_t *out_size)
{
    const uint64_t json_padded = ((uint64_t)chunks->json_length + 3) & ~(uint64_t)3;
    const uint64_t bin_padded = ((uint64_t)chunks->bin_length + 3) & ~(uint64_t)3;
    const uint64_t size = GLB_HEADER + CHUNK_HEADER + json_padded + (chunks->bin ? CHUNK_HEADER + bin_padded : 0);
    if (size > UINT32_MAX)
        return NULL;
    unsigned char *out = malloc((size_t)size);
    if (!out)
        return NULL;
    memcpy(out, "glTF", 4);
    write_u32le(out + 4, 2);
    write_u32le(out + 8, (uint32_t)size);
    size_t at = GLB_HEADER + write_chunk(out + GLB_HEADER, CHUNK_JSON, chunks->json, chunks->json_length, ' ');
    if (chunks->bin)
        write_chunk(out + at, CHUNK_BIN, chunks->bin, chunks->bin_length, 0);
    *out_size = (size_t)size;
    return out;
}
