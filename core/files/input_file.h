/* Opening a file gtlab reads: a regular file, or a one-line refusal.
 *
 * `--scene /dev/zero` grew gtlab to gigabytes, `--environment fifo` hung it
 * in open(): a reader given a device, a FIFO, a socket or a folder must say
 * what it is, at once, and read nothing. Every reader opens through here:
 * stat() first (a FIFO is never opened), then open() with O_NONBLOCK (so a
 * FIFO swapped in meanwhile cannot block it) and fstat() of what was opened
 * (the file read is the file checked), then O_NONBLOCK is cleared.
 *   gtlab: /dev/zero: is a character device, not a regular file; gtlab reads only files
 * The size returned is what the reader's declared sizes are checked
 * against before it allocates (an EXR's data window, a JSON text). */
#ifndef GTLAB_CORE_FILES_INPUT_FILE_H
#define GTLAB_CORE_FILES_INPUT_FILE_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"

/* The most bytes of pixels one stored byte of an image file decodes to, in
 * any format gtlab reads images in: OpenEXR's DWA (alpha channels: RLE 64,
 * then deflate 1032; core/files/exr_io.c lists each EXR method), above PNG's
 * deflate (1032), JPEG's (a flat 8x8 block in a few bits) and Radiance
 * HDR's RLE (64). A header claiming more pixels than its file's size times
 * this is refused before anything is allocated. */
#define INPUT_MAX_DECODE_RATIO 66048.0

/* A descriptor open for reading on the regular file `path`, and its size
 * in bytes; -1 with e = "<path>: <problem>" (missing, a folder, a device, a
 * FIFO, ...). close() it. */
int input_file_open(const char *path, int64_t *size, gt_error *e);

/* The same check for a library that opens the path itself (OpenImageIO,
 * dlopen): 0 and the size, or -1 with e. Nothing stays open. */
int input_file_check(const char *path, int64_t *size, gt_error *e);

/* The whole file, NUL-terminated (free() it), when it is a regular file of
 * at most max_size bytes; otherwise -1 with e, "<path>: <too_large>" for a
 * larger one (or one that grows while read). The buffer is sized by the
 * file, never by max_size. */
int input_file_read(const char *path, size_t max_size, const char *too_large, char **bytes, size_t *size,
                    gt_error *e);

#endif
