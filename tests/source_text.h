/* Checks on the project's own source text, shared by the one-source-per-
 * formula tests (a formula written once in a .inc, compiled as C and
 * embedded in generated shaders): a file's whole text, and that no file of
 * a list spells a fragment of the formula (a second copy). Paths are
 * relative to GTLAB_SOURCE_DIR, which the test's CMake line defines.
 * Include after "tests/check.h", with _GNU_SOURCE (open_memstream). */
#ifndef GTLAB_TESTS_SOURCE_TEXT_H
#define GTLAB_TESTS_SOURCE_TEXT_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The file's text (malloc'd, NUL-terminated), or NULL. */
static inline char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *text = NULL;
    size_t size = 0;
    if (!f)
        return NULL;
    FILE *mem = open_memstream(&text, &size);
    for (int c; (c = fgetc(f)) != EOF;)
        fputc(c, mem);
    fclose(mem);
    fclose(f);
    return text;
}

/* No file of `files` (below GTLAB_SOURCE_DIR) contains any of `prints`. */
static inline void check_no_file_spells(const char *const *files, size_t file_count, const char *const *prints,
                                        size_t print_count)
{
    for (size_t f = 0; f < file_count; ++f) {
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", GTLAB_SOURCE_DIR, files[f]);
        char *text = read_text(path);
        CHECK_MSG(text != NULL, "%s", path);
        for (size_t p = 0; text && p < print_count; ++p)
            CHECK_MSG(strstr(text, prints[p]) == NULL, "%s spells '%s'", files[f], prints[p]);
        free(text);
    }
}

#endif
