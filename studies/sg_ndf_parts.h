/* Internal to studies/sg_ndf*.c: the study's output files. */
#ifndef GTLAB_STUDIES_SG_NDF_PARTS_H
#define GTLAB_STUDIES_SG_NDF_PARTS_H

#include "studies/sg_ndf.h"

/* "ward_0.40_0.20": the material's folder and row name. */
void sg_ndf_material_name(const anisotropic_ndf *ndf, char *out, size_t size);

/* sg_ndf_lobes.json, sg_ndf_lobes.h and sg_ndf_error.dat under dir. */
int sg_ndf_write_tables(const char *dir, const sg_ndf_result *r, gt_error *e);

#endif
