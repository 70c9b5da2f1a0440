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

/* One code value of an 8-bit sRGB-encoded channel at half scale, as a
 * relative radiance change: the display's EOTF is about V^2.2, so dL / L =
 * 2.2 dV / V = 2.2 / (255 x 0.5) ~ 1.7% at V = 0.5 (less above, more below):
 * a sky pixel whose relative error stays below it moves by at most one code
 * value at mid grey and above, whatever the exposure. */
#define CLAIM_ONE_CODE_VALUE_SRGB_RELATIVE (2.2 / (255.0 * 0.5))

/* The DSSIM, (1 - SSIM) / 2, of a just noticeable difference: observers
 * begin to tell a distorted image from its original near SSIM 0.95
 * (Dosselmann and Yang, "Image quality assessment using the SSIM and the
 * just noticeable difference paradigm", 2013), so a change of DSSIM below
 * it is not a difference a viewer could see. */
#define CLAIM_DSSIM_JUST_NOTICEABLE ((1.0 - 0.95) / 2.0)

/* The contrast threshold of luminance discrimination at photopic levels
 * (Weber's law: a change of about 1% of the luminance is just visible): a
 * relative RMSE of a lit image below it changes no pixel visibly on average. */
#define CLAIM_WEBER_FRACTION 0.01

/* One CIEDE2000 unit: about the just-noticeable difference between two
 * colours seen side by side, so a graded colour that moves by less than
 * this from the exact grade cannot be told from it. */
#define CLAIM_VISIBLE_DE00 1.0

/* One code value of a unit vector stored as 0.5 n + 0.5 in an RGBA8 target
 * (a bent normal beside its AO), as an angle in degrees: a component moves
 * by 2/255 per code value, so the direction by about 2/255 rad (0.45 deg). */
#define CLAIM_ONE_CODE_VALUE_8BIT_NORMAL_DEG (2.0 / 255.0 * 57.29577951308232)

/* The mean FLIP (metrics/flip.h, flip_grey at the default 67 pixels per
 * degree) of a just noticeable change: a uniform grey moved by one
 * CIEDE2000 unit (CLAIM_VISIBLE_DE00) at mid grey, L* 49.5 -> 50.5. A
 * uniform change has no edge or point (dE_f = 0) and passes the
 * contrast-sensitivity filters unchanged, so FLIP is the colour term alone,
 * p_t / (p_c c_max) x HyAB^q_c = 0.95 / (0.4 x 41.276) x 1^0.7 = 0.0575 at
 * any viewing distance (Andersson et al. 2020, eq. 5; c_max = HyAB(green,
 * blue)^0.7). A difference of mean FLIPs below it is less than a
 * just-noticeable change over the whole image. Tested, not typed:
 * tests/report/test_flip_threshold.c. */
#define CLAIM_FLIP_JUST_NOTICEABLE 0.0575

#endif
