/* A fuzz target is libFuzzer's pair of functions: LLVMFuzzerTestOneInput
 * runs one input (any bytes) through a parser of gtlab and must neither
 * crash nor trip a sanitizer, whatever the bytes; LLVMFuzzerInitialize,
 * optional, prepares what every input shares. The same file is linked with
 * libFuzzer in the fuzz build (cmake/gtlab_fuzz.cmake) and with
 * fuzz_replay.c in every build, where ctest runs the seed corpus and every
 * input that ever crashed through it (tests/fuzz/CMakeLists.txt).
 *
 * A target may also check a property of what it parsed (a merge's header
 * agrees with its blocks); a violated property aborts, as a crash does. */
#ifndef GTLAB_TESTS_FUZZ_TARGET_H
#define GTLAB_TESTS_FUZZ_TARGET_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#ifdef __cplusplus
extern "C" {
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv);

#ifdef __cplusplus
}
#endif

/* Aborts with a message when a property of the target does not hold. */
#define FUZZ_REQUIRE(cond)                                                                  \
    do {                                                                                    \
        if (!(cond)) {                                                                      \
            fprintf(stderr, "%s:%d: fuzz property failed: %s\n", __FILE__, __LINE__, #cond); \
            abort();                                                                        \
        }                                                                                   \
    } while (0)

#endif
