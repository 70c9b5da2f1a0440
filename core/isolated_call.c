/* A function run in a child process; see isolated_call.h. */
#define _GNU_SOURCE
#include "core/isolated_call.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

/* The sanitizers' hook (libFuzzer sets it to write its crash artifact); a
 * weak reference, NULL in a build without a sanitizer runtime. */
extern void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

/* What the child sends first: the function's result (0 or -1) and the size
 * of what follows (its bytes, or its error message without the NUL). */
typedef struct {
    int32_t status;
    uint32_t reserved;
    uint64_t size;
} answer_header;

/* An answer larger than this is not one the child meant to send. */
#define ISOLATED_MAX_BYTES ((uint64_t)1 << 30)

static const int crash_signals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS};
static const int stop_signals[] = {SIGINT, SIGTERM, SIGHUP};

static int write_all(int fd, const void *data, size_t size)
{
    const char *at = data;
    while (size > 0) {
        ssize_t n = write(fd, at, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return -1;
        at += n, size -= (size_t)n;
    }
    return 0;
}

/* Seconds on the monotonic clock. */
static double monotonic_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Waits until fd can be read or the deadline (monotonic seconds; 0 for
 * none) has passed; returns 0 when it can be read, -1 at the deadline. */
static int wait_readable(int fd, double deadline)
{
    for (;;) {
        int timeout_ms = -1;
        if (deadline > 0) {
            double left = deadline - monotonic_seconds();
            if (left <= 0)
                return -1;
            timeout_ms = (int)(left * 1000.0) + 1;
        }
        int n = poll(&(struct pollfd){.fd = fd, .events = POLLIN}, 1, timeout_ms);
        if (n > 0)
            return 0;
        if (n < 0 && errno != EINTR)
            return 0; /* the read that follows says what is wrong */
    }
}

/* Reads up to size bytes before the deadline (0 for none); returns how many
 * arrived before end of file or the deadline. */
static size_t read_all(int fd, void *data, size_t size, double deadline)
{
    char *at = data;
    size_t got = 0;
    while (got < size) {
        if (wait_readable(fd, deadline) != 0)
            break;
        ssize_t n = read(fd, at + got, size - got);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        got += (size_t)n;
    }
    return got;
}

/* The child's setting (isolated_call.h): silent, default crash and stop
 * actions, no core file, no sanitizer death callback. */
static void child_defaults(int cpu_seconds)
{
    if (cpu_seconds > 0) /* SIGXCPU at the soft limit (default action: die), SIGKILL one second later */
        setrlimit(RLIMIT_CPU, &(struct rlimit){(rlim_t)cpu_seconds, (rlim_t)cpu_seconds + 1});
    signal(SIGXCPU, SIG_DFL);
    for (size_t k = 0; k < sizeof crash_signals / sizeof crash_signals[0]; ++k)
        signal(crash_signals[k], SIG_DFL);
    for (size_t k = 0; k < sizeof stop_signals / sizeof stop_signals[0]; ++k) {
        struct sigaction old;
        if (sigaction(stop_signals[k], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
            signal(stop_signals[k], SIG_DFL);
    }
    setrlimit(RLIMIT_CORE, &(struct rlimit){0, 0});
    if (__sanitizer_set_death_callback)
        __sanitizer_set_death_callback(NULL);
    int null = open("/dev/null", O_WRONLY);
    if (null >= 0) {
        dup2(null, STDOUT_FILENO);
        dup2(null, STDERR_FILENO);
        close(null);
    }
}

/* The child: runs fn, sends its answer on fd, ends. */
static void child_run(isolated_function fn, const void *context, int cpu_seconds, int fd, const sigset_t *mask)
{
    child_defaults(cpu_seconds);
    pthread_sigmask(SIG_SETMASK, mask, NULL);
    void *bytes = NULL;
    size_t size = 0;
    gt_error e = {{0}};
    int rc = fn(context, &bytes, &size, &e);
    answer_header h = {rc == 0 ? 0 : -1, 0, rc == 0 ? size : strlen(e.message)};
    int sent = write_all(fd, &h, sizeof h) == 0 && write_all(fd, rc == 0 ? bytes : e.message, h.size) == 0;
    _exit(sent ? 0 : 3);
}

/* The answer on fd: 0 (the function succeeded: *bytes, *size), -1 (it
 * failed: e holds its message) or ISOLATED_DIED (no whole answer). */
static int read_answer(int fd, double deadline, void **bytes, size_t *size, gt_error *e)
{
    answer_header h;
    if (read_all(fd, &h, sizeof h, deadline) != sizeof h || h.size > ISOLATED_MAX_BYTES || (h.status != 0 && h.status != -1))
        return ISOLATED_DIED;
    char *data = malloc(h.size + 1);
    if (!data)
        return ISOLATED_DIED;
    if (read_all(fd, data, h.size, deadline) != h.size) {
        free(data);
        return ISOLATED_DIED;
    }
    data[h.size] = '\0';
    if (h.status != 0) {
        snprintf(e->message, sizeof e->message, "%s", data);
        free(data);
        return -1;
    }
    *bytes = data;
    *size = h.size;
    return 0;
}

/* "signal 11, Segmentation fault", "exit status 1" or, killed by its CPU
 * limit, "ran over its 60 s CPU limit (signal 24)"; killed at its
 * wall-clock deadline (late), "did not answer within 122 s (killed)". */
static void describe_death(int status, int cpu_seconds, int late, char *text, size_t size)
{
    if (late)
        snprintf(text, size, "did not answer within %d s (killed)", isolated_wall_seconds(cpu_seconds));
    else if (cpu_seconds > 0 && WIFSIGNALED(status) && (WTERMSIG(status) == SIGXCPU || WTERMSIG(status) == SIGKILL))
        snprintf(text, size, "ran over its %d s CPU limit (signal %d)", cpu_seconds, WTERMSIG(status));
    else if (WIFSIGNALED(status))
        snprintf(text, size, "signal %d, %s", WTERMSIG(status), strsignal(WTERMSIG(status)));
    else if (WIFEXITED(status))
        snprintf(text, size, "exit status %d", WEXITSTATUS(status));
    else
        snprintf(text, size, "wait status %d", status);
}

/* The child's end: kills it if it is late (no whole answer by its
 * deadline), waits for it; ISOLATED_DIED unless it answered and exited
 * with 0 (answered is the answer's result). */
static int wait_child(pid_t child, int answered, int cpu_seconds, int late, const char *subject, char *death,
                      size_t death_size, gt_error *e)
{
    if (late)
        kill(child, SIGKILL);
    int status = 0;
    pid_t got;
    while ((got = waitpid(child, &status, 0)) < 0 && errno == EINTR)
        ;
    if (got < 0) /* SIGCHLD ignored: no status; the answer decides */
        status = answered == ISOLATED_DIED ? 1 << 8 : 0;
    if (answered != ISOLATED_DIED && WIFEXITED(status) && WEXITSTATUS(status) == 0)
        return answered;
    char how[128];
    describe_death(status, cpu_seconds, late, how, sizeof how);
    if (death && death_size > 0)
        snprintf(death, death_size, "%s", how);
    gt_error_set(e, subject, "the child process died (%s)", how);
    return ISOLATED_DIED;
}

/* Blocks the stop signals across fork, so that none reaches the child
 * while it still has the parent's handler (which would roll the parent's
 * output set back from the child). */
static void block_stop_signals(sigset_t *old)
{
    sigset_t blocked;
    sigemptyset(&blocked);
    for (size_t k = 0; k < sizeof stop_signals / sizeof stop_signals[0]; ++k)
        sigaddset(&blocked, stop_signals[k]);
    pthread_sigmask(SIG_BLOCK, &blocked, old);
}

int isolated_call(isolated_function fn, const void *context, const char *subject, int cpu_seconds, void **bytes,
                  size_t *size, char *death, size_t death_size, gt_error *e)
{
    gt_error ignored;
    e = e ? e : &ignored;
    *bytes = NULL, *size = 0;
    if (death && death_size > 0)
        death[0] = '\0';
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0)
        return gt_error_set(e, subject, "cannot start a child process: %s", strerror(errno));
    sigset_t mask;
    block_stop_signals(&mask);
    pid_t child = fork();
    if (child == 0) {
        close(fds[0]);
        child_run(fn, context, cpu_seconds, fds[1], &mask);
    }
    int fork_errno = errno;
    pthread_sigmask(SIG_SETMASK, &mask, NULL);
    close(fds[1]);
    if (child < 0) {
        close(fds[0]);
        return gt_error_set(e, subject, "cannot start a child process: %s", strerror(fork_errno));
    }
    const double deadline = cpu_seconds > 0 ? monotonic_seconds() + isolated_wall_seconds(cpu_seconds) : 0;
    int answered = read_answer(fds[0], deadline, bytes, size, e);
    close(fds[0]);
    const int late = answered == ISOLATED_DIED && deadline > 0 && monotonic_seconds() >= deadline;
    int rc = wait_child(child, answered, cpu_seconds, late, subject, death, death_size, e);
    if (rc == ISOLATED_DIED) {
        free(*bytes);
        *bytes = NULL, *size = 0;
    }
    return rc;
}
