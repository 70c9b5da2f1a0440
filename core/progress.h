/* A progress bar on stderr, drawn only when stderr is a terminal (so logs and
 * CI stay clean). Thread-safe: workers call progress_advance concurrently.
 *
 *   [3/23 gtao] ao boxes  [##########..........]  50.0%  12.3 s, ETA 12 s
 *
 * The bar names what it is about: the stage of `gtlab all`
 * (progress_set_stage), the scene a render is of (progress_set_subject) and
 * its own label. A render in several passes (a checkpointed render's blocks,
 * raytracer/render_checkpoint.c) is one bar: between progress_span_begin and
 * progress_span_end each pass's bar draws its work as its part of the whole
 * (progress_span_part), so the bar does not restart at every pass. A bar
 * ended before its work was done (an interruption) stays where it was. */
#ifndef GTLAB_CORE_PROGRESS_H
#define GTLAB_CORE_PROGRESS_H

#include <stdint.h>

typedef struct {
    const char *label;
    int64_t total;
    int64_t done;   /* updated atomically */
    int64_t drawn;  /* last value drawn */
    int drawing;    /* a thread is drawing (the others skip: draws stay in order) */
    double start_seconds;
    int enabled;
} progress;

void progress_begin(progress *p, const char *label, int64_t total);
void progress_advance(progress *p, int64_t amount);
void progress_end(progress *p);

/* The stage and the subject drawn before every bar (copied; NULL or "":
 * none). Set from the main thread between bars. */
void progress_set_stage(const char *text);
void progress_set_subject(const char *text);

/* A whole of `total` units drawn by the bars until progress_span_end; the
 * next bar's work is units [before, before + size) of it. */
void progress_span_begin(int64_t total);
void progress_span_part(int64_t before, int64_t size);
void progress_span_end(void);

/* "12 s", "4 min 10 s", "1 h 05 min": a duration for people. */
void progress_duration_text(double seconds, char *out, int size);

/* Wall-clock seconds from a monotonic clock. */
double seconds_now(void);

#endif
