/* EXR files through the OpenEXR C API (OpenEXRCore): float32 channels, one
 * part, ZIP compression, string header attributes. Writes go to a temporary
 * file in the same folder and are renamed into place only when complete, so a
 * failure never leaves a half-written output. */
#ifndef GTLAB_CORE_FILES_EXR_IO_H
#define GTLAB_CORE_FILES_EXR_IO_H

#include "core/error.h"
#include "core/image.h"

/* Writes every channel of img as FLOAT, and every attribute as an EXR string
 * attribute. Returns 0, or -1 with e = "<path>: <problem>". */
int exr_write(const char *path, const image *img, gt_error *e);

/* Reads every channel (HALF and UINT converted to float) and every string
 * attribute of the first part. Scanline and tiled files. Returns 0, or -1 with
 * e = "<path>: <problem>" (missing file, not an EXR, truncated, ...). */
int exr_read(const char *path, image *img, gt_error *e);
/* The same from a file's bytes in memory; `name` stands for the file in
 * messages. */
int exr_read_memory(const void *bytes, size_t size, const char *name, image *img, gt_error *e);

#endif
