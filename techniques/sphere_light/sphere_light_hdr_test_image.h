/* An HDR test image for the image-space studies (dithering, bloom): gtlab's
 * unshadowed sphere-light reference of builtin:sphere-on-plane (light at
 * (-2.5, 4, 1.5), radius 0.5, radiance 5; camera from (0, 3, 7) at
 * (0, 0.7, 0), 40 degrees), the scene INSIDE's talk lights with one sphere
 * light. Part of the sphere light's study: the dither and bloom techniques
 * both start from it (techniques/dither/, techniques/bloom/: USES
 * sphere_light). */
#ifndef GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_HDR_TEST_IMAGE_H
#define GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_HDR_TEST_IMAGE_H

#include "core/image.h"
#include "project/study_context.h"

/* width x height at spp samples per pixel, seed seed, ctx->threads threads:
 * the reference's channels (CH_SPHERE_*, CH_MASK) into out. */
int hdr_test_image_sphere_light(const study_context *ctx, int width, int height, int spp, unsigned seed, image *out,
                                gt_error *e);

#endif
