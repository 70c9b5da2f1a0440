/* The sub-pixel shift between an image a and a reference b, by least
 * squares on b's gradient: a - b ~= d . grad b (first order in the shift d,
 * pixels), over the pixels inside the mask whose four neighbours are inside
 * too (central differences). d = M^-1 v with M = sum g g^T, v = sum g r.
 * Its standard error is clustered by b x b blocks (neighbouring pixels'
 * residuals are correlated): the sandwich M^-1 (sum_k s_k s_k^T) M^-1 with
 * s_k = v_k - M_k d the block's score; the sums over blocks are kept as
 * moments so images (scenes) pool into one accumulator before d is known. */
#ifndef GTLAB_METRICS_SHIFT_FIT_H
#define GTLAB_METRICS_SHIFT_FIT_H

typedef struct {
    long blocks, pixels;
    double m[2][2], v[2];      /* sum over blocks of M_k, v_k */
    double vv[2][2];           /* sum v_k v_k^T */
    double vm[2][2][2];        /* sum v_k,i M_k,jl */
    double mm[2][2][2][2];     /* sum M_k,ij M_k,kl */
} shift_fit;

void shift_fit_add(shift_fit *s, const float *a, const float *b, const float *mask, int width, int height,
                   int block);
/* d and its standard errors; 0 with a singular M. */
void shift_fit_solve(const shift_fit *s, double d[2], double se[2]);
/* The RMS change of b per pixel of shift along u, sqrt(u^T M u / pixels):
 * a shift t u changes b by t times this, RMS over the fitted pixels (to
 * first order), so a shift's visible effect is in b's units. 0 without
 * pixels. */
double shift_fit_rms_gradient(const shift_fit *s, const double u[2]);

#endif
