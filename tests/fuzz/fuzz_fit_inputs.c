/* Fuzz target "fit_inputs": an EXR file (the input is its bytes) as each
 * fit reads its inputs before fitting: a multi-bounce reference
 * (`gtlab fit multibounce --data`, techniques/multibounce/multibounce_fit.h), a
 * specular-occlusion reference with its AO (`gtlab fit aperture`; here the
 * same file is both, specular_occlusion/specular_occlusion_inputs.h), and a G-buffer
 * with its camera (`gtlab fit gtao-params` and `gtlab approx`,
 * project/gbuffer_input.h). The fits themselves run on what these accept. */
#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "multibounce/multibounce_fit.h"
#include "specular_occlusion/aperture_fit.h"
#include "fuzz_target.h"
#include "project/gbuffer_input.h"
#include "specular_occlusion/specular_occlusion_inputs.h"

static void read_as_fit_inputs(const image *img)
{
    gt_error e;
    static multibounce_data d;
    multibounce_data_init(&d);
    (void)multibounce_data_add_image(&d, img, "fuzz.exr", &e);
    multibounce_data_free(&d);
    aperture_case c;
    (void)aperture_case_from_images(&c, img, "fuzz.exr", img, "fuzz.exr", CH_SPECOCC, &e);
    aperture_case_free(&c); /* it starts by clearing c: freeing after a failure is safe */
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    approx_input in;
    gt_error e;
    if (exr_read_memory(data, size, "/nonexistent-gtlab-fuzz/fuzz.exr", &in.img, &e) != 0)
        return 0;
    read_as_fit_inputs(&in.img);
    /* approx_from_image takes the image over (and frees it on failure). */
    if (approx_from_image("/nonexistent-gtlab-fuzz/fuzz.exr", NULL, &in, &e) == 0)
        approx_input_free(&in);
    return 0;
}
