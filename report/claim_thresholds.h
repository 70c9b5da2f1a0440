/* Visibility thresholds: the tolerances a claim may take from the output
 * the technique feeds when the claim's own words give no number
 * (docs/claims-protocol.md, "Where a tolerance comes from"). Each is
 * justified once, there; a section cites the constant, never a number of
 * its own. */
#ifndef GTLAB_REPORT_CLAIM_THRESHOLDS_H
#define GTLAB_REPORT_CLAIM_THRESHOLDS_H

/* One code value of an 8-bit UNORM target (an AO or specular-occlusion
 * buffer in R8, a colour channel of an RGBA8 G-buffer or back buffer):
 * a change smaller than this cannot reach the screen through that target. */
#define CLAIM_ONE_CODE_VALUE_8BIT (1.0 / 255.0)

/* The squared error of one 8-bit code value: a difference of mean squared
 * errors smaller than this moves no pixel by a code value on average. */
#define CLAIM_ONE_CODE_VALUE_8BIT_MSE (CLAIM_ONE_CODE_VALUE_8BIT * CLAIM_ONE_CODE_VALUE_8BIT)

/* A 1% change of luminance as a log ratio (ln 1.01 ~ 0.00995, taken as
 * 0.01): the Weber fraction of photopic vision is about 1-2%, so a mean
 * |log error| that changes by less cannot be told apart. */
#define CLAIM_VISIBLE_LOG_LUMINANCE 0.01

/* One CIEDE2000 unit: about the just-noticeable difference between two
 * colours seen side by side, so a graded colour that moves by less than
 * this from the exact grade cannot be told from it. */
#define CLAIM_VISIBLE_DE00 1.0

#endif
