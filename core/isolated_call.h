/* A function run in a child process, so that a library which crashes on
 * some input (glslang on malformed HLSL: issue 41) cannot take gtlab down
 * with it. The child (fork, no exec) runs the function and sends its answer
 * back through a pipe: the bytes it made, or its error. A child that dies
 * before its whole answer arrived (a signal, a sanitizer's exit) is
 * reported in words and never kills the caller.
 *
 * In the child, before the function runs:
 *  - stdout and stderr go to /dev/null (a crashing library's or a
 *    sanitizer's report would be extra lines on the user's terminal);
 *  - the crash signals (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP,
 *    SIGSYS) get their default action and core files are off, so a crash
 *    kills the child by that signal whatever a sanitizer or fuzzer
 *    installed (and no sanitizer's death callback writes a fuzzer
 *    artifact); SIGINT, SIGTERM and SIGHUP their default action unless
 *    ignored (the output set's handler is the parent's: the child must not
 *    roll the run back);
 *  - only the calling thread exists (fork copies one), so the function
 *    must not start threads through OpenMP (the parent's pool is not
 *    there); it may allocate and read files.
 *  - with cpu_seconds > 0, at most that much CPU time (RLIMIT_CPU): a
 *    library that loops on some input is killed by SIGXCPU and reported
 *    like a crash ("ran over its 60 s CPU limit"), never hangs the caller;
 *    and at most isolated_wall_seconds(cpu_seconds) of wall-clock time: a
 *    child that waits for ever uses no CPU (a lock some other thread of
 *    the parent held at the fork, which no thread of the child will
 *    release: glibc's malloc is safe across fork, a sanitizer runtime's
 *    allocator is not), and is killed at that deadline ("did not answer
 *    within 122 s (killed)").
 * The child ends with _exit: no atexit handler, no leak check, no stdio
 * buffer of the parent's flushed twice. */
#ifndef GTLAB_CORE_ISOLATED_CALL_H
#define GTLAB_CORE_ISOLATED_CALL_H

#include <stddef.h>

#include "core/error.h"

/* The function: 0 with *bytes (malloc'd, may be NULL when *size is 0) and
 * *size set, or -1 with e set. */
typedef int (*isolated_function)(const void *context, void **bytes, size_t *size, gt_error *e);

enum { ISOLATED_DIED = -2 };

/* The wall-clock time a child with a CPU limit of cpu_seconds is given:
 * twice its CPU time and 2 s, room enough for a machine loaded by other
 * work. */
static inline int isolated_wall_seconds(int cpu_seconds) { return 2 * cpu_seconds + 2; }

/* Runs fn(context, ...) in a child process (cpu_seconds: its CPU time
 * limit, 0 for none). Returns 0 with *bytes (malloc'd,
 * the caller frees it; never NULL on success) and *size; -1 with e = the
 * function's own error, or the caller's `subject` and the problem when no
 * child could be started or its answer read; ISOLATED_DIED when the child
 * died without a whole answer, with `death` (if non-NULL, death_size bytes)
 * saying how: "signal 11, Segmentation fault", "exit status 1" (a
 * sanitizer that found an error exits so), "ran over its 60 s CPU limit
 * (signal 24)" or "did not answer within 122 s (killed)", and e = "<subject>: the child
 * process died (<how>)" for callers that need no words of their own. */
int isolated_call(isolated_function fn, const void *context, const char *subject, int cpu_seconds, void **bytes,
                  size_t *size, char *death, size_t death_size, gt_error *e);

#endif
