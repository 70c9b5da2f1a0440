/* The bloom study's pyramids (bloom_study.h): an HDR render downsampled
 * level by level with the target kernel, with the 9 fitted taps, and with
 * the talk's policy (9 taps at exact halves, the target elsewhere), scored
 * per level by DSSIM of x / (1 + x) after an exposure putting the render's
 * 99th percentile at 1. */
#ifndef GTLAB_BLOOM_BLOOM_PYRAMID_H
#define GTLAB_BLOOM_BLOOM_PYRAMID_H

#include "bloom/bloom_study.h"

int bloom_pyramids(const study_context *ctx, const bloom_request *rq, bloom_result *out, gt_error *e);

#endif
