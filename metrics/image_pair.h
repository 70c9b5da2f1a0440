/* What every comparison of two gtlab EXR images sets up first: the channel
 * compared, the mask both images agree on (mask.A; see image_error.h for the
 * mask convention), and the checks that make the pair comparable (same size,
 * finite values). */
#ifndef GTLAB_METRICS_IMAGE_PAIR_H
#define GTLAB_METRICS_IMAGE_PAIR_H

#include "core/error.h"
#include "core/image.h"
#include "metrics/image_error.h"

/* Channels compared when none is named, in order of preference; NULL-terminated. */
extern const char *const metrics_default_channels[];

/* One channel of two images, ready to compare. */
typedef struct {
    char channel[IMAGE_NAME_MAX];
    int width, height;
    const float *a, *b; /* the channel's planes, owned by the images */
    float *mask;        /* owned: 1 where both images' mask.A is inside (an image
                           without mask.A counts as all inside), else 0 */
} metrics_pair;

/* Sets up the comparison of image a (named what_a in errors, usually its
 * path) with image b. `channel` NULL chooses the first of
 * metrics_default_channels present in both. Returns 0, or -1 with e naming
 * the file at fault: sizes differ; the channel is missing (the message lists
 * the file's channels); a value of the channel is NaN or infinite (every
 * pixel is checked, since SSIM windows reach outside the mask); out of memory.
 * On failure nothing needs freeing. */
int metrics_pair_init(metrics_pair *pair, const image *a, const char *what_a, const image *b, const char *what_b,
                      const char *channel, gt_error *e);
void metrics_pair_free(metrics_pair *pair);

#endif
