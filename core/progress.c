#define _POSIX_C_SOURCE 200809L
#include "core/progress.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void draw(const progress *p, int64_t done)
{
    const int width = 40;
    double fraction = p->total > 0 ? (double)done / (double)p->total : 1.0;
    int filled = (int)(fraction * width);
    double elapsed = seconds_now() - p->start_seconds;
    char bar[64];
    for (int i = 0; i < width; ++i)
        bar[i] = i < filled ? '#' : '.';
    bar[width] = '\0';
    fprintf(stderr, "\r%-12s [%s] %5.1f%%  %6.1fs", p->label, bar, 100.0 * fraction, elapsed);
    fflush(stderr);
}

void progress_begin(progress *p, const char *label, int64_t total)
{
    p->label = label;
    p->total = total;
    p->done = 0;
    p->drawn = 0;
    p->start_seconds = seconds_now();
    p->enabled = isatty(STDERR_FILENO);
    if (p->enabled)
        draw(p, 0);
}

void progress_advance(progress *p, int64_t amount)
{
    int64_t done = __atomic_add_fetch(&p->done, amount, __ATOMIC_RELAXED);
    if (!p->enabled)
        return;
    /* Redraw at most every 1/200 of the work, from whichever thread crosses it. */
    int64_t step = p->total / 200 > 0 ? p->total / 200 : 1;
    int64_t drawn = __atomic_load_n(&p->drawn, __ATOMIC_RELAXED);
    if (done - drawn >= step &&
        __atomic_compare_exchange_n(&p->drawn, &drawn, done, 0, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {
        draw(p, done);
    }
}

void progress_end(progress *p)
{
    if (!p->enabled)
        return;
    draw(p, p->total);
    fputc('\n', stderr);
}
