/* Internal to the sg_ndf study: the study's output files. */
#ifndef GTLAB_SG_NDF_PARTS_H
#define GTLAB_SG_NDF_PARTS_H

#include "sg_ndf/sg_ndf_study.h"

/* "ward_0.40_0.20": the material's folder and row name. */
void sg_ndf_material_name(const anisotropic_ndf *ndf, char *out, size_t size);

/* sg_ndf_lobes.json, sg_ndf_lobes.h and sg_ndf_error.dat under dir. */
int sg_ndf_write_tables(const char *dir, const sg_ndf_result *r, gt_error *e);

#endif
