/* The SG NDF study end to end on a small request: the lobe tables it
 * writes agree with its results struct (the JSON's lobes are the fits'
 * lobes, the header holds one table per checked fit), the least k for the
 * target is the first fit under it, and the images were scored. */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "sg_ndf/sg_ndf_study.h"
#include "tests/check.h"

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = calloc((size_t)n + 1, 1);
    if (s && fread(s, 1, (size_t)n, f) != (size_t)n)
        s[0] = '\0';
    fclose(f);
    return s;
}

int main(void)
{
    char dir[512], path[600];
    snprintf(dir, sizeof dir, "%s/sg_ndf_study", check_tmp_dir());
    mkdir(dir, 0755);
    study_context ctx = {dir, QUALITY_PREVIEW, 2, NULL, NULL, 0};
    sg_ndf_request rq = sg_ndf_default_request(QUALITY_PREVIEW);
    rq.material_count = 1;
    rq.materials[0] = (anisotropic_ndf){NDF_WARD, 0.3, 0.1};
    rq.imaged[0] = 1;
    rq.max_lobes = 4;
    rq.image_size = 24;
    rq.image_samples = 64;
    rq.l2_target = 0.1;
    static sg_ndf_result r;
    gt_error e = {{0}};
    CHECK_MSG(sg_ndf_study(&ctx, &rq, &r, &e) == 0, "%s", e.message);
    const sg_ndf_material *m = &r.materials[0];
    CHECK(m->fitted == 4 && m->has_images);
    int first = 0;
    for (int k = 1; k <= m->fitted && !first; ++k)
        first = m->fits[k - 1].l2_error <= rq.l2_target ? k : 0;
    CHECK(m->lobes_for_target == first && first > 1);
    CHECK(m->dssim[0] > 0.0 && m->noise_floor_dssim > 0.0);
    snprintf(path, sizeof path, "%s/%s/sg_ndf_lobes.json", dir, SG_NDF_DIR);
    char *text = slurp(path);
    cJSON *root = text ? cJSON_Parse(text) : NULL;
    CHECK(root != NULL);
    cJSON *fits = cJSON_GetObjectItem(cJSON_GetArrayItem(cJSON_GetObjectItem(root, "materials"), 0), "fits");
    CHECK(cJSON_GetArraySize(fits) == 4);
    cJSON *lobe = cJSON_GetArrayItem(cJSON_GetObjectItem(cJSON_GetArrayItem(fits, 2), "lobes"), 1);
    CHECK(lobe && cJSON_GetObjectItem(lobe, "sharpness")->valuedouble == m->fits[2].lobes[1].sharpness);
    cJSON_Delete(root);
    free(text);
    snprintf(path, sizeof path, "%s/%s/sg_ndf_lobes.h", dir, SG_NDF_DIR);
    text = slurp(path);
    CHECK(text && strstr(text, "ward_0_30_0_10_k4[4]") && !strstr(text, "_k5["));
    free(text);
    snprintf(path, sizeof path, "%s/%s/ward_0.30_0.10/k4.png", dir, SG_NDF_DIR);
    FILE *png = fopen(path, "rb");
    CHECK(png != NULL);
    if (png)
        fclose(png);
    return check_report("test_sg_ndf_study");
}
