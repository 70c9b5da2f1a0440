/* distributed_render.h with MPI: films travel to rank 0 as raw bytes (the
 * ranks of one job run one build on one architecture) in chunks below
 * MPI's int count, and are added there in rank order (mc_film_merge). */
#include <limits.h>
#include <mpi.h>
#include <stdlib.h>

#include "raytracer/distributed_render.h"

enum { FILM_TAG = 20, PLANES = 5 };
#define CHUNK_BYTES ((size_t)1 << 30)

static int joined; /* distributed_begin initialised MPI */
static int alone;  /* distributed_render_alone: each rank renders by itself */

/* The launchers set these in every process they start: Open MPI's mpirun,
 * PMI (MPICH, srun --mpi=pmi2) and PMIx (srun --mpi=pmix). */
static int started_by_launcher(void)
{
    return getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMI_SIZE") || getenv("PMIX_RANK");
}

static void finalize_at_exit(void)
{
    int done = 0;
    MPI_Finalized(&done);
    if (!done)
        MPI_Finalize();
}

void distributed_render_alone(void) { alone = 1; }

int distributed_begin(gt_error *e)
{
    if (joined || !started_by_launcher())
        return 0;
    int provided; /* only the main thread calls MPI; OpenMP threads sample */
    if (MPI_Init_thread(NULL, NULL, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
        return gt_error_set(e, "mpirun", "MPI_Init_thread failed");
    atexit(finalize_at_exit);
    joined = 1;
    return 0;
}

render_share distributed_job(void)
{
    render_share s = {0, 1};
    if (joined) {
        MPI_Comm_rank(MPI_COMM_WORLD, &s.rank);
        MPI_Comm_size(MPI_COMM_WORLD, &s.ranks);
    }
    return s;
}

render_share distributed_share(void) { return alone ? (render_share){0, 1} : distributed_job(); }

typedef struct {
    void *data;
    size_t bytes;
} film_plane;

/* The film's accumulator arrays: what a rank contributes. */
static void film_planes(const mc_film *f, film_plane planes[PLANES])
{
    size_t pixels = (size_t)f->width * (size_t)f->height, n = pixels * (size_t)f->quantity_count;
    planes[0] = (film_plane){f->sum, n * sizeof *f->sum};
    planes[1] = (film_plane){f->sum_even, n * sizeof *f->sum_even};
    planes[2] = (film_plane){f->moments, n * sizeof *f->moments};
    planes[3] = (film_plane){f->count, pixels * sizeof *f->count};
    planes[4] = (film_plane){f->count_even, pixels * sizeof *f->count_even};
}

/* Sends the film's planes to rank 0, or receives them from rank `from`
 * into it, chunk by chunk. */
static int transfer_film(mc_film *film, int receive_from)
{
    film_plane planes[PLANES];
    film_planes(film, planes);
    int rc = MPI_SUCCESS;
    for (int k = 0; k < PLANES; ++k)
        for (size_t at = 0; at < planes[k].bytes && rc == MPI_SUCCESS; at += CHUNK_BYTES) {
            char *chunk = (char *)planes[k].data + at;
            int n = (int)(planes[k].bytes - at < CHUNK_BYTES ? planes[k].bytes - at : CHUNK_BYTES);
            rc = receive_from > 0
                     ? MPI_Recv(chunk, n, MPI_BYTE, receive_from, FILM_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
                     : MPI_Send(chunk, n, MPI_BYTE, 0, FILM_TAG, MPI_COMM_WORLD);
        }
    return rc == MPI_SUCCESS ? 0 : -1;
}

/* Rank 0: every other rank's film, received and added in rank order. */
static int gather_films(mc_film *film, int ranks, gt_error *e)
{
    mc_film part;
    if (mc_film_init(&part, film->width, film->height, film->quantities, film->quantity_count) != 0)
        return gt_error_set(e, "mpirun", "out of memory for a rank's film");
    int rc = 0;
    for (int r = 1; r < ranks && rc == 0; ++r) {
        if (transfer_film(&part, r) != 0)
            rc = gt_error_set(e, "mpirun", "receiving rank %d's film failed", r);
        else
            rc = mc_film_merge(film, &part, "mpirun", e);
    }
    mc_film_free(&part);
    return rc;
}

/* Rays and samples summed, seconds the longest rank's, on rank 0. */
static void reduce_stats(render_stats *stats, int rank)
{
    uint64_t counts[2] = {stats->rays, stats->samples}, total[2] = {0, 0};
    double longest = 0.0;
    MPI_Reduce(counts, total, 2, MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
    MPI_Reduce(&stats->seconds, &longest, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    if (rank == 0)
        *stats = (render_stats){total[0], total[1], longest};
}

int distributed_reduce_film(mc_film *film, render_stats *stats, gt_error *e)
{
    render_share share = distributed_share();
    if (share.ranks == 1)
        return 0;
    int rc = 0;
    if (share.rank == 0)
        rc = gather_films(film, share.ranks, e);
    else if (transfer_film(film, 0) != 0)
        rc = gt_error_set(e, "mpirun", "sending rank %d's film failed", share.rank);
    reduce_stats(stats, share.rank);
    return rc;
}

int distributed_all(int ok)
{
    int all = ok != 0;
    if (distributed_job().ranks > 1)
        MPI_Allreduce(MPI_IN_PLACE, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    return all;
}
