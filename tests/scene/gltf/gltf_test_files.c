/* Crafted glTF files and stderr capture for the glTF tests. */
#define _POSIX_C_SOURCE 200809L
#include "gltf_test_files.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../check.h"
#include "scene/gltf/gltf_reader.h"

const char *tmp_path(const char *name)
{
    static char path[4096];
    snprintf(path, sizeof path, "%s/%s", check_tmp_dir(), name);
    return path;
}

int write_bytes(const char *path, const void *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    int ok = fwrite(data, 1, size, f) == size;
    ok = (fclose(f) == 0) && ok;
    return ok ? 0 : -1;
}

char *base64_encode(const void *data, size_t size)
{
    static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const unsigned char *in = data;
    char *out = malloc(4 * ((size + 2) / 3) + 1);
    char *o = out;
    for (size_t i = 0; i < size; i += 3) {
        uint32_t v = (uint32_t)in[i] << 16;
        if (i + 1 < size)
            v |= (uint32_t)in[i + 1] << 8;
        if (i + 2 < size)
            v |= in[i + 2];
        *o++ = alphabet[(v >> 18) & 63];
        *o++ = alphabet[(v >> 12) & 63];
        *o++ = i + 1 < size ? alphabet[(v >> 6) & 63] : '=';
        *o++ = i + 2 < size ? alphabet[v & 63] : '=';
    }
    *o = '\0';
    return out;
}

char *data_uri(const void *data, size_t size)
{
    static const char header[] = "data:application/octet-stream;base64,";
    char *b64 = base64_encode(data, size);
    char *uri = malloc(sizeof header + strlen(b64));
    strcpy(uri, header);
    strcat(uri, b64);
    free(b64);
    return uri;
}

static void put_u32(unsigned char *p, uint32_t v)
{
    for (int i = 0; i < 4; ++i)
        p[i] = (unsigned char)(v >> (8 * i)); /* little-endian, as GLB requires */
}

unsigned char *glb_bytes(const char *json, const void *bin, size_t bin_size, size_t *out_size)
{
    size_t json_size = strlen(json), json_padded = (json_size + 3) & ~(size_t)3;
    size_t bin_padded = (bin_size + 3) & ~(size_t)3;
    size_t total = 12 + 8 + json_padded + (bin_size ? 8 + bin_padded : 0);
    unsigned char *out = calloc(1, total);
    memcpy(out, "glTF", 4);
    put_u32(out + 4, 2);
    put_u32(out + 8, (uint32_t)total);
    put_u32(out + 12, (uint32_t)json_padded);
    put_u32(out + 16, 0x4E4F534Au); /* "JSON" */
    memcpy(out + 20, json, json_size);
    memset(out + 20 + json_size, ' ', json_padded - json_size);
    if (bin_size) {
        unsigned char *chunk = out + 20 + json_padded;
        put_u32(chunk, (uint32_t)bin_padded);
        put_u32(chunk + 4, 0x004E4942u); /* "BIN\0" */
        memcpy(chunk + 8, bin, bin_size);
    }
    *out_size = total;
    return out;
}

int load_capturing(const char *path, scene *s, gt_error *e, char *printed, size_t printed_size)
{
    fflush(stderr);
    int saved = dup(fileno(stderr));
    FILE *f = tmpfile();
    dup2(fileno(f), fileno(stderr));
    int rc = gltf_load(path, s, e);
    fflush(stderr);
    dup2(saved, fileno(stderr));
    close(saved);
    rewind(f);
    size_t n = fread(printed, 1, printed_size - 1, f);
    printed[n] = '\0';
    fclose(f);
    if (n > 0) /* show what was captured, so a failing run explains itself */
        fprintf(stderr, "[%s printed]\n%s", path, printed);
    return rc;
}

int only_warnings(const char *printed)
{
    static const char prefix[] = "gtlab: warning: ";
    for (const char *line = printed; *line;) {
        if (strncmp(line, prefix, sizeof prefix - 1) != 0)
            return 0;
        const char *end = strchr(line, '\n');
        if (!end)
            return 0; /* every warning ends its line */
        line = end + 1;
    }
    return 1;
}
