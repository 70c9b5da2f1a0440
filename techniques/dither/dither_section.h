/* Dithering and blue noise (INSIDE, GDC 2016; dither_study.h): the
 * patterns at equal noise power on a gradient and an HDR render, the
 * R11G11B10 rows, and the talk's claims. */
#ifndef GTLAB_DITHER_DITHER_SECTION_H
#define GTLAB_DITHER_DITHER_SECTION_H

#include "dither/dither_study.h"
#include "report/report_context.h"

/* Adds the section to ctx's report, summary.json and claims; -1 (e set) on failure. */
int dither_section(report_context *ctx, const dither_result *r, gt_error *e);

#endif
