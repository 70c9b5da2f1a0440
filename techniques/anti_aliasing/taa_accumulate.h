/* A conventional accumulating TAA (Karis 2014, "High Quality Temporal
 * Supersampling"; the baseline of issue 19): each frame is rendered with a
 * Halton (2, 3) jitter (taa_sampling.h) and blended into an exponential
 * history,
 *     out(c) = (1 - alpha) clamp(H(c + m), lo, hi) + alpha I(c),
 * H the previous output fetched bilinearly at the pixel centre c plus its
 * motion vector m, [lo, hi] the per-channel min / max box of the current
 * frame's 3 x 3 neighbourhood (neighbourhood clamp, not variance clipping:
 * our choice, the simpler and the one Karis starts from), I the current
 * jittered sample taken as the pixel's value (no unjittering filter). With
 * no history (first frame) or history from outside the previous image the
 * output is I. alpha 0.1 is the usual weight. */
#ifndef GTLAB_ANTI_ALIASING_TAA_ACCUMULATE_H
#define GTLAB_ANTI_ALIASING_TAA_ACCUMULATE_H

typedef struct {
    double alpha; /* weight of the current frame, 0.1 */
} taa_accumulate_settings;

taa_accumulate_settings taa_accumulate_default_settings(void);

/* One frame: current and out W x H RGB, motion 2 floats a pixel, history the
 * previous out or NULL. out must not alias history or current. */
void taa_accumulate(const taa_accumulate_settings *s, const float *current, const float *motion, const float *history,
                    int width, int height, int threads, float *out);

#endif
