/* The GLB container (scene/gltf/glb_container.h): a well-formed file splits into
 * chunks that lie inside it; every cut of it, and every length field that
 * points past the bytes there, is refused with one line. Among them the
 * file tinygltf 2.7.0 reads 8 bytes past: a BIN chunk whose data would end
 * 8 bytes beyond the end (it checks the chunk without its 8-byte header). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "scene/gltf/glb_container.h"
#include "tests/check.h"

enum { JSON_LENGTH = 28, BIN_LENGTH = 8, FILE_LENGTH = 12 + 8 + JSON_LENGTH + 8 + BIN_LENGTH };

static void put_u32(unsigned char *p, uint32_t v)
{
    for (int k = 0; k < 4; ++k)
        p[k] = (unsigned char)(v >> (8 * k));
}

/* header, JSON chunk {"asset":{"version":"2.0"}} padded, BIN chunk of 8 bytes */
static void make_glb(unsigned char glb[FILE_LENGTH])
{
    memcpy(glb, "glTF", 4);
    put_u32(glb + 4, 2);
    put_u32(glb + 8, FILE_LENGTH);
    put_u32(glb + 12, JSON_LENGTH);
    memcpy(glb + 16, "JSON", 4);
    memcpy(glb + 20, "{\"asset\":{\"version\":\"2.0\"}}  ", JSON_LENGTH);
    put_u32(glb + 20 + JSON_LENGTH, BIN_LENGTH);
    memcpy(glb + 24 + JSON_LENGTH, "BIN", 4);
    memset(glb + 28 + JSON_LENGTH, 0xab, BIN_LENGTH);
}

static void check_refused(const unsigned char *glb, size_t size, const char *expected)
{
    glb_chunks c;
    gt_error e = {{0}};
    CHECK_MSG(glb_split(glb, size, "f.glb", &c, &e) == -1, "accepted: %s", expected);
    CHECK_MSG(strstr(e.message, expected) != NULL, "\n  got      '%s'\n  expected '%s'", e.message, expected);
}

static void test_split(void)
{
    unsigned char glb[FILE_LENGTH];
    make_glb(glb);
    glb_chunks c;
    gt_error e;
    CHECK(glb_split(glb, sizeof glb, "f.glb", &c, &e) == 0);
    CHECK(c.json == glb + 20 && c.json_length == JSON_LENGTH);
    CHECK(c.bin == glb + 28 + JSON_LENGTH && c.bin_length == BIN_LENGTH);
    /* Without the BIN chunk; and with trailing bytes beyond the length. */
    put_u32(glb + 8, 20 + JSON_LENGTH);
    CHECK(glb_split(glb, sizeof glb, "f.glb", &c, &e) == 0 && c.bin == NULL && c.bin_length == 0);
}

static void test_every_cut(void)
{
    unsigned char glb[FILE_LENGTH];
    make_glb(glb);
    for (size_t size = 0; size < sizeof glb; ++size) {
        unsigned char *cut = malloc(size ? size : 1); /* exactly the bytes there */
        memcpy(cut, glb, size);
        glb_chunks c;
        gt_error e = {{0}};
        CHECK_MSG(glb_split(cut, size, "f.glb", &c, &e) == -1, "cut at %zu accepted", size);
        CHECK(strncmp(e.message, "f.glb: ", 7) == 0);
        free(cut);
    }
}

static void test_lengths(void)
{
    unsigned char glb[FILE_LENGTH];
    make_glb(glb);
    put_u32(glb + 4, 1);
    check_refused(glb, sizeof glb, "GLB version 1 is not supported: gtlab reads binary glTF 2.0");
    make_glb(glb);
    put_u32(glb + 8, FILE_LENGTH + 1);
    check_refused(glb, sizeof glb, "GLB header gives a length of 65 bytes but the file has 64 (truncated?)");
    make_glb(glb);
    put_u32(glb + 12, UINT32_MAX);
    check_refused(glb, sizeof glb, "GLB JSON chunk of 4294967295 bytes runs past the end");
    make_glb(glb);
    put_u32(glb + 12, 0);
    check_refused(glb, sizeof glb, "does not start with a JSON chunk");
    make_glb(glb);
    memcpy(glb + 16, "BIN", 4);
    check_refused(glb, sizeof glb, "does not start with a JSON chunk");
    make_glb(glb);
    memcpy(glb + 24 + JSON_LENGTH, "JSON", 4);
    check_refused(glb, sizeof glb, "GLB second chunk is not BIN");
    make_glb(glb);
    put_u32(glb + 20 + JSON_LENGTH, 6);
    check_refused(glb, sizeof glb, "GLB BIN chunk of 6 bytes is not a positive multiple of 4");
    /* tinygltf's overrun: chunk header + data end 8 bytes past the file,
     * the data alone (what tinygltf checks) just fits. */
    make_glb(glb);
    put_u32(glb + 20 + JSON_LENGTH, BIN_LENGTH + 8);
    check_refused(glb, sizeof glb, "GLB BIN chunk of 16 bytes runs past the end of the file (truncated?)");
    make_glb(glb);
    put_u32(glb + 20 + JSON_LENGTH, UINT32_MAX - 3);
    check_refused(glb, sizeof glb, "GLB BIN chunk of 4294967292 bytes runs past the end");
}

int main(void)
{
    test_split();
    test_every_cut();
    test_lengths();
    return check_report("test_glb_container");
}
