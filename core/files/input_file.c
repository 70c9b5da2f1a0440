/* Regular files only, opened without blocking; see input_file.h. */
#define _POSIX_C_SOURCE 200809L
#include "core/files/input_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* What a file that is not a regular one is, in words. */
static const char *file_kind(mode_t mode)
{
    return S_ISDIR(mode)    ? "a directory"
           : S_ISCHR(mode)  ? "a character device"
           : S_ISBLK(mode)  ? "a block device"
           : S_ISFIFO(mode) ? "a FIFO (named pipe)"
           : S_ISSOCK(mode) ? "a socket"
                            : "not a regular file";
}

static int refuse_kind(const char *path, mode_t mode, gt_error *e)
{
    return gt_error_set(e, path, "is %s, not a regular file; gtlab reads only files", file_kind(mode));
}

int input_file_open(const char *path, int64_t *size, gt_error *e)
{
    struct stat st;
    if (!path || !*path)
        return gt_error_set(e, "gtlab", "no input file given");
    if (stat(path, &st) != 0)
        return gt_error_set(e, path, "cannot open: %s", strerror(errno));
    if (!S_ISREG(st.st_mode))
        return refuse_kind(path, st.st_mode, e);
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return gt_error_set(e, path, "cannot open: %s", strerror(errno));
    int flags = fcntl(fd, F_GETFL);
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0) {
        int err = errno;
        close(fd);
        return S_ISREG(st.st_mode) ? gt_error_set(e, path, "cannot open: %s", strerror(err))
                                   : refuse_kind(path, st.st_mode, e);
    }
    *size = (int64_t)st.st_size;
    return fd;
}

int input_file_check(const char *path, int64_t *size, gt_error *e)
{
    int64_t n;
    int fd = input_file_open(path, &n, e);
    if (fd < 0)
        return -1;
    close(fd);
    if (size)
        *size = n;
    return 0;
}

int input_file_read(const char *path, size_t max_size, const char *too_large, char **bytes, size_t *size,
                    gt_error *e)
{
    *bytes = NULL;
    int64_t length;
    int fd = input_file_open(path, &length, e);
    if (fd < 0)
        return -1;
    if ((uint64_t)length > max_size) {
        close(fd);
        return gt_error_set(e, path, "%s", too_large);
    }
    /* One byte more than the file held at fstat: a file that grew since is
     * seen to, and refused. */
    size_t capacity = (size_t)length + 1, used = 0;
    char *buffer = malloc(capacity + 1);
    ssize_t n = 0;
    while (buffer && used < capacity && (n = read(fd, buffer + used, capacity - used)) != 0) {
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            break;
        used += (size_t)n;
    }
    int err = errno;
    close(fd);
    if (!buffer)
        return gt_error_set(e, path, "out of memory for its %lld bytes", (long long)length);
    if (n < 0 || used > (size_t)length) {
        free(buffer);
        return n < 0 ? gt_error_set(e, path, "cannot read: %s", strerror(err))
                     : gt_error_set(e, path, "grew while gtlab read it");
    }
    buffer[used] = '\0';
    *bytes = buffer;
    *size = used;
    return 0;
}
