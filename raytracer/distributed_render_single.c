/* distributed_render.h without MPI: one process, rank 0 of 1. */
#include <stdlib.h>

#include "raytracer/distributed_render.h"

/* mpirun sets the job's size in the environment of every process it starts. */
static int started_by_mpirun(void)
{
    const char *size = getenv("OMPI_COMM_WORLD_SIZE");
    return size && atoi(size) > 1;
}

int distributed_begin(gt_error *e)
{
    if (started_by_mpirun())
        return gt_error_set(e, "mpirun", "this gtlab was built without MPI (GTLAB_MPI=OFF or no libopenmpi-dev "
                                         "at configure time): each process would render the whole image; run it "
                                         "without mpirun or rebuild with MPI");
    return 0;
}

render_share distributed_share(void) { return (render_share){0, 1}; }
render_share distributed_job(void) { return (render_share){0, 1}; }
void distributed_render_alone(void) {}

int distributed_reduce_film(mc_film *film, render_stats *stats, gt_error *e)
{
    (void)film, (void)stats, (void)e;
    return 0;
}

int distributed_all(int ok) { return ok != 0; }
