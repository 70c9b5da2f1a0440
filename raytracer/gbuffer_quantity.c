/* `gtlab render gbuffer`: the G-buffer alone (raytracer/gbuffer.h), which
 * every other quantity writes too. No sampling, so no options and no
 * sampling header. */
#include "raytracer/reference_render.h"

const reference_quantity_descriptor reference_quantity_gbuffer = {
    .name = "gbuffer",
    .help = "depth.Z, N.*, Ng.*, P.*, albedo.*, roughness.Y, mask.A",
};
