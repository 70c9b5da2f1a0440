/* Reference files into the multi-bounce refit's samples
 * (multibounce_fit_input.h). */
#include "studies/multibounce_fit_input.h"

#include "core/exr_io.h"

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
