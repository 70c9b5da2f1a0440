/* Reference files into the multi-bounce refit's samples
 * (multibounce_fit_input.h). */
#include "multibounce/multibounce_fit_input.h"

#include <stdlib.h>

#include "core/files/exr_io.h"

int multibounce_fit_input_load(const char *const *files, int count, multibounce_data *d, gt_error *e)
{
    for (int i = 0; i < count; ++i) {
        image img;
        if (exr_read(files[i], &img, e) != 0)
            return -1;
        int rc = multibounce_data_add_image(d, &img, files[i], e);
        image_free(&img);
        if (rc != 0)
            return -1;
    }
    multibounce_data_weigh(d);
    return 0;
}

int multibounce_fit_files(const char *const *files, int count, const char *command_line,
                          const multibounce_output_files *out, FILE *report, gt_error *e)
{
    multibounce_data d;
    multibounce_data_init(&d);
    multibounce_analysis *a = malloc(sizeof *a);
    int rc = !a ? gt_error_set(e, "fit multibounce", "out of memory")
             : multibounce_fit_input_load(files, count, &d, e) != 0 || multibounce_analyse(&d, a, e) != 0 ||
                     multibounce_write_outputs(&d, a, command_line, out->json, out->header, out->hlsl, out->glsl,
                                               e) != 0
                 ? -1
                 : 0;
    if (rc == 0)
        multibounce_analysis_print(report, &d, a);
    free(a);
    multibounce_data_free(&d);
    return rc;
}
