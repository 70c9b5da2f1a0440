/* What the MPI and the single-process builds of distributed_render.h share. */
#include "raytracer/distributed_render.h"

sampling_settings distributed_sample_share(const sampling_settings *ss, render_share share)
{
    sampling_settings mine = *ss;
    uint64_t begin = (uint64_t)ss->spp * (uint64_t)share.rank / (uint64_t)share.ranks;
    uint64_t end = (uint64_t)ss->spp * (uint64_t)(share.rank + 1) / (uint64_t)share.ranks;
    mine.sample_offset = ss->sample_offset + (uint32_t)begin;
    mine.spp = (int)(end - begin);
    return mine;
}

int distributed_is_writer(void) { return distributed_share().rank == 0; }
