#include "studies/study.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

int study_make_dir(const study_context *ctx, const char *sub, char *path, size_t size, gt_error *e)
{
    snprintf(path, size, "%s/%s", ctx->output_dir, sub);
    if (mkdir(path, 0755) != 0 && errno != EEXIST)
        return gt_error_set(e, path, "cannot create folder: %s", strerror(errno));
    return 0;
}
