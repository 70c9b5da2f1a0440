/* Kaplanyan 2010's precision figures (hdr_precision_study.h): gamma vs
 * linear storage and the HDR lower bounds, beside the talk's numbers, with
 * the typos the computation exposes (figures/hdr_code_steps.png). */
#ifndef GTLAB_HDR_PRECISION_SECTION_H
#define GTLAB_HDR_PRECISION_SECTION_H

#include "report/report_context.h"
#include "hdr_precision/hdr_precision_study.h"

/* The three claims rows (the equal-precision point, the two lower bounds);
 * a NULL table ignores them. */
void hdr_precision_add_claims(claims_table *t, const hdr_precision_result *r);
int hdr_precision_section(report_context *ctx, const hdr_precision_result *r, gt_error *e);

#endif
