/* A progress bar on stderr, drawn only when stderr is a terminal (so logs and
 * CI stay clean). Thread-safe: workers call progress_advance concurrently. */
#ifndef GTLAB_CORE_PROGRESS_H
#define GTLAB_CORE_PROGRESS_H

#include <stdint.h>

typedef struct {
    const char *label;
    int64_t total;
    int64_t done;   /* updated atomically */
    int64_t drawn;  /* last value drawn */
    double start_seconds;
    int enabled;
} progress;

void progress_begin(progress *p, const char *label, int64_t total);
void progress_advance(progress *p, int64_t amount);
void progress_end(progress *p);

/* Wall-clock seconds from a monotonic clock. */
double seconds_now(void);

#endif
