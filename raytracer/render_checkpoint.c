/* Rendering in blocks with checkpoints (render_checkpoint.h). */
#define _POSIX_C_SOURCE 200809L
#include "raytracer/render_checkpoint.h"

#include <inttypes.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/files/exr_io.h"
#include "core/files/output_set.h"
#include "core/progress.h"
#include "core/reference_schema.h"
#include "raytracer/distributed_render.h"
#include "raytracer/sample_blocks.h"

static volatile sig_atomic_t stop_signal; /* the signal that asked to stop, or 0 */

static void on_stop_signal(int signal_number) { stop_signal = signal_number; }

static const int stop_signals[3] = {SIGINT, SIGTERM, SIGHUP};

/* While rendering, the stop signals only set stop_signal (a signal the
 * parent ignores stays ignored); `saved` keeps the handlers to restore. */
static void catch_stop_signals(struct sigaction saved[3])
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    stop_signal = 0;
    for (int i = 0; i < 3; ++i)
        if (sigaction(stop_signals[i], NULL, &saved[i]) == 0 && saved[i].sa_handler != SIG_IGN)
            sigaction(stop_signals[i], &sa, NULL);
}

static void restore_stop_signals(const struct sigaction saved[3])
{
    for (int i = 0; i < 3; ++i)
        sigaction(stop_signals[i], &saved[i], NULL);
}

/* What a block is: CHECKPOINT_BLOCK samples of every pixel (a fixed spp),
 * or CHECKPOINT_ROWS rows, each pixel to its stopping target (adaptive).
 * Under mpirun the samples are the rank's share (ss is already it), and the
 * rows rank r's of N: rows r, r + N, r + 2N, ..., counted 0, 1, 2, ... */
typedef struct {
    int by_rows;
    uint32_t total, step;  /* samples or rows */
    int first_row, stride; /* row k of this process is first_row + k * stride */
} block_units;

static block_units units_of(const gbuffer *gb, const sampling_settings *ss, render_share share)
{
    int rows = ss->threads * 4 > CHECKPOINT_ROWS ? ss->threads * 4 : CHECKPOINT_ROWS; /* keep every thread busy */
    int my_rows = gb->height > share.rank ? (gb->height - share.rank + share.ranks - 1) / share.ranks : 0;
    if (ss->target_stderr > 0.0 || ss->target_rel_stderr > 0.0)
        return (block_units){1, (uint32_t)my_rows, (uint32_t)rows, share.rank, share.ranks};
    return (block_units){0, (uint32_t)distributed_sample_share(ss, share).spp, CHECKPOINT_BLOCK, 0, 1};
}

/* "r/N" for rank r of N (N > 1), else "": what ATTR_CHECKPOINT_RANK holds. */
static void rank_text(char *out, size_t size)
{
    render_share share = distributed_share();
    if (share.ranks > 1)
        snprintf(out, size, "%d/%d", share.rank, share.ranks);
    else
        out[0] = '\0';
}

static double env_number(const char *name, double fallback)
{
    const char *text = getenv(name);
    char *end;
    double v = text ? strtod(text, &end) : fallback;
    return text && (end == text || *end != '\0' || v < 0.0) ? fallback : v;
}

/* The film and the samples done, written as a hidden temporary (in the
 * output set: a rollback removes it) and renamed onto cp->path outside it. */
static int write_checkpoint(const render_checkpoint *cp, const sampling_settings *ss, block_units u, uint32_t done,
                            const mc_film *film, gt_error *e)
{
    char temp[4096];
    snprintf(temp, sizeof temp, "%s.writing-%ld", cp->path, (long)getpid());
    image img;
    if (image_init(&img, film->width, film->height) != 0)
        return gt_error_set(e, cp->path, "out of memory for the checkpoint");
    int rc = mc_film_write_channels(film, &img) | image_set_attribute(&img, ATTR_CHECKPOINT_OF, cp->identity);
    char blocks[64], rows[32], rank[32];
    rank_text(rank, sizeof rank);
    if (rank[0])
        rc |= image_set_attribute(&img, ATTR_CHECKPOINT_RANK, rank);
    snprintf(blocks, sizeof blocks, "%" PRIu32 ":%" PRIu32 "+%" PRIu32, ss->seed, ss->sample_offset,
             u.by_rows ? (uint32_t)ss->spp : done);
    rc |= image_set_attribute(&img, ATTR_BLOCKS, blocks);
    snprintf(rows, sizeof rows, "%" PRIu32, done);
    if (u.by_rows)
        rc |= image_set_attribute(&img, ATTR_CHECKPOINT_ROWS, rows);
    if (rc != 0)
        rc = gt_error_set(e, cp->path, "out of memory for the checkpoint");
    else if ((rc = exr_write(temp, &img, e)) == 0 && rename(temp, cp->path) != 0)
        rc = gt_error_set(e, cp->path, "cannot rename the checkpoint into place");
    image_free(&img);
    return rc;
}

/* The rows an adaptive render's checkpoint holds, at most the image's. */
static int checkpoint_rows(const image *img, const render_checkpoint *cp, block_units u, uint32_t *done,
                           gt_error *e)
{
    const char *text = image_get_attribute(img, ATTR_CHECKPOINT_ROWS);
    char *end;
    unsigned long rows = text ? strtoul(text, &end, 10) : 0;
    if (!text || end == text || *end != '\0' || rows > u.total)
        return gt_error_set(e, cp->path, "no valid %s (the rows an adaptive render finished)", ATTR_CHECKPOINT_ROWS);
    *done = (uint32_t)rows;
    return 0;
}

/* The value of `key` in an identity's "key=value" lines (its length in *n), or NULL. */
static const char *identity_value(const char *identity, const char *key, size_t key_length, int *n)
{
    for (const char *line = identity; *line;) {
        const char *end = strchr(line, '\n');
        size_t length = end ? (size_t)(end - line) : strlen(line);
        if (length > key_length && strncmp(line, key, key_length) == 0 && line[key_length] == '=') {
            *n = (int)(length - key_length - 1);
            return line + key_length + 1;
        }
        line += length + (end ? 1 : 0);
    }
    return NULL;
}

/* What differs between a checkpoint's identity and this render's: the first
 * header attribute of this render whose value there differs ("gtlab.spp is
 * 1024 there, 2048 here"), values cut at 60 characters. */
static void identity_difference(const char *theirs, const char *ours, char *out, size_t size)
{
    snprintf(out, size, "its %s differs", ATTR_CHECKPOINT_OF);
    for (const char *line = ours; *line;) {
        const char *end = strchr(line, '\n'), *equals = strchr(line, '=');
        size_t length = end ? (size_t)(end - line) : strlen(line);
        if (equals && (size_t)(equals - line) < length) {
            size_t key_length = (size_t)(equals - line);
            int n = 0, ours_n = (int)(length - key_length - 1);
            const char *value = identity_value(theirs, line, key_length, &n);
            if (!value || n != ours_n || strncmp(value, equals + 1, (size_t)n) != 0) {
                char there[80], here[80];
                snprintf(there, sizeof there, value ? "%.*s%s" : "absent%.*s%s", value ? (n < 60 ? n : 60) : 0,
                         value ? value : "", value && n > 60 ? "..." : "");
                snprintf(here, sizeof here, "%.*s%s", ours_n < 60 ? ours_n : 60, equals + 1, ours_n > 60 ? "..." : "");
                snprintf(out, size, "its %.*s is %s there, %s here", (int)key_length, line, there, here);
                return;
            }
        }
        line += length + (end ? 1 : 0);
    }
}

/* The samples the checkpoint holds: one block of this render's seed from
 * its offset, at most its spp (adaptive: all of them, and the rows done). */
static int checkpoint_done(const image *img, const render_checkpoint *cp, const sampling_settings *ss,
                           block_units u, uint32_t *done, gt_error *e)
{
    const char *of = image_get_attribute(img, ATTR_CHECKPOINT_OF);
    const char *its_rank = image_get_attribute(img, ATTR_CHECKPOINT_RANK);
    char rank[32];
    rank_text(rank, sizeof rank);
    if (!of || strcmp(of, cp->identity) != 0) {
        char what[512];
        identity_difference(of ? of : "", cp->identity, what, sizeof what);
        return gt_error_set(e, cp->path, "a checkpoint of another render (%s): remove it, or render without "
                                         "--resume",
                            what);
    }
    if (strcmp(its_rank ? its_rank : "", rank) != 0)
        return gt_error_set(e, cp->path, "a checkpoint of another process (its %s is '%s', this one's '%s')",
                            ATTR_CHECKPOINT_RANK, its_rank ? its_rank : "", rank);
    sample_block b;
    int n;
    if (sample_blocks_parse(image_get_attribute(img, ATTR_BLOCKS), cp->path, &b, 1, &n, e) != 0)
        return -1;
    if (b.seed != ss->seed || b.begin != ss->sample_offset || b.end > (uint64_t)ss->sample_offset + ss->spp ||
        (u.by_rows && b.end != (uint64_t)ss->sample_offset + ss->spp))
        return gt_error_set(e, cp->path, "its %s is not a start of this render's samples", ATTR_BLOCKS);
    *done = (uint32_t)(b.end - b.begin);
    return u.by_rows ? checkpoint_rows(img, cp, u, done, e) : 0;
}

/* With --resume and a checkpoint at cp->path, its sums into the (empty)
 * film and the samples they hold; else 0 done. */
static int resume_from(const render_checkpoint *cp, const sampling_settings *ss, block_units u, mc_film *film,
                       uint32_t *done, gt_error *e)
{
    *done = 0;
    if (!cp->resume || access(cp->path, F_OK) != 0)
        return 0;
    image img;
    mc_film saved;
    if (exr_read(cp->path, &img, e) != 0)
        return -1;
    int rc = checkpoint_done(&img, cp, ss, u, done, e);
    if (rc == 0 && (rc = mc_film_read_channels(&img, cp->path, &saved, e)) == 0) {
        rc = mc_film_merge(film, &saved, cp->path, e);
        mc_film_free(&saved);
    }
    image_free(&img);
    return rc;
}

/* The block after `done` (u.step samples or rows, fewer at the end). */
static uint32_t block_size(block_units u, uint32_t done)
{
    return u.total - done < u.step ? u.total - done : u.step;
}

/* A block of this process's rows straight into the film: its rows were
 * empty before, so an interrupted block is taken back by emptying them. */
static int render_row_block(const gbuffer *gb, const integrator *it, const sampling_settings *ss, block_units u,
                            uint32_t done, uint32_t size, mc_film *film, render_stats *stats)
{
    int first = u.first_row + (int)done * u.stride, end = u.first_row + (int)(done + size) * u.stride;
    int rc = render_estimates_add_rows(gb, it, ss, first, u.stride, end, film, stats, &stop_signal);
    for (int y = first; rc != 0 && y < end && y < gb->height; y += u.stride)
        mc_film_clear_rows(film, y, y + 1);
    return rc;
}

/* The block after `done` added to the film (samples through a film of
 * their own, merged), so an interrupted block leaves the total as it was.
 * Returns 0, 1 when stopped, or -1 with e. */
static int render_block(const gbuffer *gb, const integrator *it, const sampling_settings *ss, block_units u,
                        uint32_t done, mc_film *film, render_stats *stats, const char *what, gt_error *e)
{
    sampling_settings b = *ss;
    uint32_t size = block_size(u, done);
    if (u.by_rows)
        return render_row_block(gb, it, ss, u, done, size, film, stats);
    b.sample_offset = ss->sample_offset + done, b.spp = (int)size;
    mc_film block;
    if (render_estimates_film(gb, it, &block, e) != 0)
        return -1;
    int rc = render_estimates_add(gb, it, &b, &block, stats, &stop_signal);
    if (rc == 0)
        rc = mc_film_merge(film, &block, what, e);
    mc_film_free(&block);
    return rc;
}

/* What an interrupted render says as it exits (core/files/output_set.h):
 * where its samples are kept and how to go on. */
static void note_checkpoint_kept(const render_checkpoint *cp, block_units u, uint32_t done)
{
    char line[1024];
    snprintf(line, sizeof line,
             "gtlab: interrupted: %s keeps the %u of %u %s done; the same command with --resume continues from "
             "there\n",
             cp->path, done, u.total, u.by_rows ? "rows" : "samples per pixel");
    output_set_interrupt_note(line);
}

/* Renders the blocks after `done`, writing the checkpoint every interval
 * and when stopped. */
static int render_blocks(const gbuffer *gb, const integrator *it, const sampling_settings *ss,
                         const render_checkpoint *cp, block_units u, uint32_t done, mc_film *film, render_stats *stats,
                         gt_error *e)
{
    const double interval = env_number("GTLAB_CHECKPOINT_SECONDS", CHECKPOINT_SECONDS);
    const double stop_after = env_number("GTLAB_STOP_AFTER_BLOCKS", 0.0);
    double last = seconds_now();
    uint32_t written = done;
    int rc = 0;
    progress_span_begin(u.total); /* one bar for all the blocks */
    for (int blocks = 1; rc == 0 && done < u.total && !stop_signal; ++blocks) {
        progress_span_part(done, block_size(u, done));
        if ((rc = render_block(gb, it, ss, u, done, film, stats, cp->path, e)) != 0)
            break;
        done += block_size(u, done);
        if (stop_after > 0 && blocks >= stop_after)
            stop_signal = SIGTERM; /* the test hook: as if the scheduler stopped the job */
        if (done < u.total && seconds_now() - last >= interval) {
            rc = write_checkpoint(cp, ss, u, done, film, e);
            last = seconds_now(), written = done;
        }
    }
    progress_span_end();
    if (rc >= 0 && stop_signal && done > written)
        rc = write_checkpoint(cp, ss, u, done, film, e);
    if (rc >= 0 && stop_signal && done > 0)
        note_checkpoint_kept(cp, u, done);
    return rc < 0 ? -1 : 0;
}

int render_estimates_checkpointed(const gbuffer *gb, const integrator *it, const sampling_settings *ss,
                                  const render_checkpoint *cp, mc_film *film, render_stats *stats, gt_error *e)
{
    if (render_estimates_film(gb, it, film, e) != 0)
        return -1;
    *stats = (render_stats){0, 0, 0.0};
    struct sigaction saved[3];
    catch_stop_signals(saved);
    uint32_t done;
    const render_share share = distributed_share();
    const block_units u = units_of(gb, ss, share);
    const sampling_settings mine = u.by_rows ? *ss : distributed_sample_share(ss, share);
    int rc = resume_from(cp, &mine, u, film, &done, e);
    if (rc == 0)
        rc = render_blocks(gb, it, &mine, cp, u, done, film, stats, e);
    const int stopped_by = stop_signal;
    restore_stop_signals(saved);
    if (stopped_by)
        raise(stopped_by); /* gtlab's handler: roll back, exit 128 + signal */
    if (!distributed_all(rc == 0) && rc == 0) /* under mpirun no rank waits for a failed one's film */
        rc = gt_error_set(e, cp->path, "another rank failed (its error is above): nothing written");
    if (rc == 0)
        rc = distributed_reduce_film(film, stats, e); /* under mpirun: the job's film on rank 0 */
    if (rc != 0)
        mc_film_free(film);
    return rc;
}
