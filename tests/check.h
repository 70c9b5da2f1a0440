/* Minimal assertions for the test executables: every failed CHECK prints the
 * file, line and the values involved; main returns check_report(). */
#ifndef GTLAB_TESTS_CHECK_H
#define GTLAB_TESTS_CHECK_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int check_failures = 0;
static int check_count = 0;

#define CHECK(cond)                                                                  \
    do {                                                                             \
        ++check_count;                                                               \
        if (!(cond)) {                                                               \
            ++check_failures;                                                        \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
        }                                                                            \
    } while (0)

#define CHECK_MSG(cond, ...)                                                         \
    do {                                                                             \
        ++check_count;                                                               \
        if (!(cond)) {                                                               \
            ++check_failures;                                                        \
            fprintf(stderr, "%s:%d: CHECK failed: %s: ", __FILE__, __LINE__, #cond); \
            fprintf(stderr, __VA_ARGS__);                                            \
            fputc('\n', stderr);                                                     \
        }                                                                            \
    } while (0)

#define CHECK_NEAR(a, b, tol)                                                                     \
    do {                                                                                          \
        double check_a_ = (a), check_b_ = (b), check_t_ = (tol);                                  \
        ++check_count;                                                                            \
        if (!(fabs(check_a_ - check_b_) <= check_t_)) {                                           \
            ++check_failures;                                                                     \
            fprintf(stderr, "%s:%d: CHECK_NEAR failed: %s = %.9g, %s = %.9g, tolerance %.3g\n", \
                    __FILE__, __LINE__, #a, check_a_, #b, check_b_, check_t_);                    \
        }                                                                                         \
    } while (0)

static inline int check_report(const char *name)
{
    printf("%s: %d checks, %d failed\n", name, check_count, check_failures);
    return check_failures ? 1 : 0;
}

/* A scratch folder for files a test writes (set by CMake). */
static inline const char *check_tmp_dir(void)
{
    const char *d = getenv("GTLAB_TEST_TMP");
    return d ? d : "/tmp";
}

#endif
