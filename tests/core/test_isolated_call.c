/* core/isolated_call.h: a function run in a child process hands back its
 * bytes (more than a pipe holds) or its error; a child that crashes, aborts
 * or exits is reported and the test process lives on; the child's stderr
 * never reaches ours; the output set's stop handler is not the child's (a
 * SIGTERM there kills the child, it does not roll our files back), and a
 * signal we ignore stays ignored in it; a child that waits for ever is
 * killed at its wall-clock deadline. */
#define _GNU_SOURCE
#include <pthread.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/files/atomic_file.h"
#include "core/isolated_call.h"
#include "core/files/output_set.h"
#include "tests/check.h"

enum { BIG = 3 << 20 }; /* 3 MiB: far more than a pipe's buffer (64 KiB) */

/* The byte k of the big answer. */
static unsigned char pattern(size_t k) { return (unsigned char)(k * 2654435761u >> 13); }

static int make_big(const void *context, void **bytes, size_t *size, gt_error *e)
{
    (void)context, (void)e;
    unsigned char *b = malloc(BIG);
    for (size_t k = 0; b && k < BIG; ++k)
        b[k] = pattern(k);
    *bytes = b, *size = BIG;
    return b ? 0 : -1;
}

static int make_nothing(const void *context, void **bytes, size_t *size, gt_error *e)
{
    (void)context, (void)e;
    *bytes = NULL, *size = 0;
    return 0;
}

static int fail_in_words(const void *context, void **bytes, size_t *size, gt_error *e)
{
    (void)bytes, (void)size;
    return gt_error_set(e, context, "no such thing");
}

/* Writes to stderr, then dies by the signal *context. */
static int noisy_death(const void *context, void **bytes, size_t *size, gt_error *e)
{
    (void)bytes, (void)size, (void)e;
    fprintf(stderr, "a library's last words\n");
    fflush(stderr);
    raise(*(const int *)context);
    return 0;
}

static int exit_early(const void *context, void **bytes, size_t *size, gt_error *e)
{
    (void)context, (void)bytes, (void)size, (void)e;
    _exit(1);
}

/* A member of a null object read, as glslang's (issue 41): address 8, in
 * the unmapped first page (not NULL itself, which UBSan's null check would
 * catch first in the sanitizer build; glslang is not instrumented). */
static int null_read(const void *context, void **bytes, size_t *size, gt_error *e)
{
    (void)context, (void)bytes, (void)size, (void)e;
    volatile int *volatile member = (volatile int *)(uintptr_t)8;
    return *member;
}

static void test_answers(void)
{
    void *bytes;
    size_t size;
    gt_error e = {{0}};
    CHECK(isolated_call(make_big, NULL, "big", 0, &bytes, &size, NULL, 0, &e) == 0 && size == BIG);
    int wrong = 0;
    for (size_t k = 0; bytes && k < size; ++k)
        wrong += ((unsigned char *)bytes)[k] != pattern(k);
    CHECK_MSG(wrong == 0, "%d of %d bytes differ", wrong, BIG);
    free(bytes);
    CHECK(isolated_call(make_nothing, NULL, "empty", 0, &bytes, &size, NULL, 0, &e) == 0 && size == 0 && bytes);
    free(bytes);
    CHECK(isolated_call(fail_in_words, "thing.txt", "x", 0, &bytes, &size, NULL, 0, &e) == -1 && !bytes && size == 0);
    CHECK_MSG(strcmp(e.message, "thing.txt: no such thing") == 0, "%s", e.message);
}

/* Our stderr (fd 2) into a file for the call; what the call wrote there. */
static long stderr_bytes_during(isolated_function fn, const void *context, int *rc, char *death, size_t size)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/isolated_call_stderr.txt", check_tmp_dir());
    fflush(stderr);
    int saved = dup(2);
    FILE *f = fopen(path, "w");
    dup2(fileno(f), 2);
    void *bytes;
    size_t n;
    gt_error e = {{0}};
    *rc = isolated_call(fn, context, "noisy", 0, &bytes, &n, death, size, &e);
    free(bytes);
    dup2(saved, 2);
    close(saved);
    fclose(f);
    struct stat st;
    long written = stat(path, &st) == 0 ? (long)st.st_size : -1;
    remove(path);
    return written;
}

static void test_deaths(void)
{
    char death[128];
    void *bytes;
    size_t size;
    gt_error e = {{0}};
    int rc = isolated_call(null_read, NULL, "null.hlsl", 0, &bytes, &size, death, sizeof death, &e);
    CHECK(rc == ISOLATED_DIED && !bytes && size == 0);
    CHECK_MSG(strncmp(death, "signal 11, ", 11) == 0, "%s", death);
    CHECK_MSG(strncmp(e.message, "null.hlsl: the child process died (signal 11, ", 46) == 0, "%s", e.message);
    static const int fatal[] = {SIGSEGV, SIGABRT, SIGBUS, SIGFPE};
    for (size_t k = 0; k < sizeof fatal / sizeof fatal[0]; ++k) {
        char expected[32];
        snprintf(expected, sizeof expected, "signal %d, ", fatal[k]);
        long written = stderr_bytes_during(noisy_death, &fatal[k], &rc, death, sizeof death);
        CHECK_MSG(rc == ISOLATED_DIED && strncmp(death, expected, strlen(expected)) == 0, "%d: %s", fatal[k], death);
        CHECK_MSG(written == 0, "signal %d: %ld bytes on our stderr", fatal[k], written);
    }
    CHECK(isolated_call(exit_early, NULL, "x", 0, &bytes, &size, death, sizeof death, &e) == ISOLATED_DIED);
    CHECK_MSG(strcmp(death, "exit status 1") == 0, "%s", death);
}

/* A function that never returns (a library looping on its input). */
static int spin_forever(const void *context, void **bytes, size_t *size, gt_error *e)
{
    (void)context, (void)bytes, (void)size, (void)e;
    for (volatile unsigned long k = 0;; ++k)
        ;
    return 0;
}

/* A child over its CPU limit is killed and said so; the caller goes on, and
 * a quick function under the same limit answers as without one. */
static void test_cpu_limit(void)
{
    char death[128];
    void *bytes;
    size_t size;
    gt_error e = {{0}};
    CHECK(isolated_call(spin_forever, NULL, "loop.hlsl", 1, &bytes, &size, death, sizeof death, &e) == ISOLATED_DIED);
    CHECK_MSG(strncmp(death, "ran over its 1 s CPU limit (signal ", 35) == 0, "%s", death);
    CHECK_MSG(strstr(e.message, "loop.hlsl: the child process died (ran over its 1 s CPU limit") == e.message, "%s",
              e.message);
    CHECK(isolated_call(make_nothing, NULL, "quick", 1, &bytes, &size, NULL, 0, &e) == 0 && size == 0 && bytes);
    free(bytes);
}

/* Locks the mutex *context: in the child, one the parent held at the fork
 * (as a sanitizer's allocator lock another thread held), which no thread
 * of the child will ever release. */
static int lock_held_mutex(const void *context, void **bytes, size_t *size, gt_error *e)
{
    (void)bytes, (void)size, (void)e;
    pthread_mutex_lock((pthread_mutex_t *)context);
    return 0;
}

/* A child that waits for ever, using no CPU, is killed at its wall-clock
 * deadline and said so; the caller goes on. */
static void test_wall_deadline(void)
{
    static pthread_mutex_t held = PTHREAD_MUTEX_INITIALIZER;
    char death[128];
    void *bytes;
    size_t size;
    gt_error e = {{0}};
    pthread_mutex_lock(&held);
    CHECK(isolated_call(lock_held_mutex, &held, "locked.hlsl", 1, &bytes, &size, death, sizeof death, &e) ==
          ISOLATED_DIED);
    pthread_mutex_unlock(&held);
    CHECK(isolated_wall_seconds(1) == 4);
    CHECK_MSG(strcmp(death, "did not answer within 4 s (killed)") == 0, "%s", death);
    CHECK_MSG(strcmp(e.message, "locked.hlsl: the child process died (did not answer within 4 s (killed))") == 0, "%s",
              e.message);
    CHECK(!bytes && size == 0);
}

/* A file committed in an open output set survives a SIGTERM in the child
 * (which dies by it); an ignored SIGINT stays ignored there. */
static void test_stop_signals(void)
{
    char path[4096], death[128];
    snprintf(path, sizeof path, "%s/isolated_call_kept.txt", check_tmp_dir());
    gt_error e = {{0}};
    output_set_install_signal_handlers();
    output_set_begin();
    CHECK(atomic_write_text(path, "kept", &e) == 0);
    void *bytes;
    size_t size;
    static const int term = SIGTERM, interrupt = SIGINT;
    int rc = isolated_call(noisy_death, &term, "x", 0, &bytes, &size, death, sizeof death, &e);
    CHECK_MSG(rc == ISOLATED_DIED && strncmp(death, "signal 15, ", 11) == 0, "%s", death);
    CHECK_MSG(access(path, F_OK) == 0, "the child rolled the parent's output set back");
    CHECK(output_set_commit(&e) == 0);
    remove(path);
    struct sigaction ignore = {.sa_handler = SIG_IGN}, old;
    sigaction(SIGINT, &ignore, &old);
    stderr_bytes_during(noisy_death, &interrupt, &rc, death, sizeof death);
    CHECK_MSG(rc == 0, "an ignored SIGINT killed the child: %d %s", rc, death);
    sigaction(SIGINT, &old, NULL);
}

int main(void)
{
    test_answers();
    test_deaths();
    test_cpu_limit();
    test_wall_deadline();
    test_stop_signals();
    return check_report("test_isolated_call");
}
