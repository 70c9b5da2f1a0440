/* The cone/lobe table as shipped: BC4, slice by slice (see the header). */
#include "specular_occlusion/bc4_codec.h"
#include "specular_occlusion/specular_occlusion_lut.h"

#include <stdlib.h>
#include <string.h>

int so_lut_bc4(const so_lut *src, so_lut *dst)
{
    size_t n = (size_t)src->size, slice = n * n;
    *dst = *src;
    dst->bc4 = 1;
    dst->data = malloc(sizeof *dst->data * slice * n);
    unsigned char *blocks = malloc(bc4_storage_bytes(src->size, src->size));
    if (!dst->data || !blocks) {
        free(blocks);
        so_lut_free(dst);
        return -1;
    }
    for (size_t k = 0; k < n; ++k) {
        bc4_encode(src->data + k * slice, src->size, src->size, blocks);
        bc4_decode(blocks, src->size, src->size, dst->data + k * slice);
    }
    free(blocks);
    return 0;
}
