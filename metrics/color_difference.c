/* CIEDE2000 through Little CMS 2 (color_difference.h). */
#include "metrics/color_difference.h"

#include <lcms2.h>
#include <stdlib.h>

struct color_difference {
    cmsHTRANSFORM to_lab; /* sRGB doubles in [0, 1] -> Lab doubles */
};

color_difference *color_difference_create(gt_error *e)
{
    color_difference *cd = calloc(1, sizeof *cd);
    cmsHPROFILE srgb = cmsCreate_sRGBProfile(), lab = cmsCreateLab4Profile(NULL);
    if (cd && srgb && lab)
        cd->to_lab = cmsCreateTransform(srgb, TYPE_RGB_DBL, lab, TYPE_Lab_DBL, INTENT_RELATIVE_COLORIMETRIC,
                                        cmsFLAGS_NOCACHE);
    if (srgb)
        cmsCloseProfile(srgb);
    if (lab)
        cmsCloseProfile(lab);
    if (!cd || !cd->to_lab) {
        free(cd);
        return gt_error_set(e, "Little CMS", "cannot build the sRGB to Lab transform"), NULL;
    }
    return cd;
}

void color_difference_free(color_difference *cd)
{
    if (!cd)
        return;
    cmsDeleteTransform(cd->to_lab);
    free(cd);
}

enum { CHUNK = 256 };

void color_difference_ciede2000(const color_difference *cd, const double *a, const double *b, size_t count,
                                double *delta)
{
    cmsCIELab la[CHUNK], lb[CHUNK];
    for (size_t start = 0; start < count; start += CHUNK) {
        size_t n = count - start < CHUNK ? count - start : CHUNK;
        cmsDoTransform(cd->to_lab, a + 3 * start, la, (cmsUInt32Number)n);
        cmsDoTransform(cd->to_lab, b + 3 * start, lb, (cmsUInt32Number)n);
        for (size_t i = 0; i < n; ++i)
            delta[start + i] = cmsCIE2000DeltaE(&la[i], &lb[i], 1.0, 1.0, 1.0);
    }
}
