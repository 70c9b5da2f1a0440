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

static char stage_text[128], subject_text[128];

/* The span the bars belong to (progress_span_begin): its whole, the current
 * part and when it began; active 0: each bar is its own whole. */
static struct {
    int active, drawn;
    int64_t total, before, size;
    double start_seconds;
} span;

void progress_set_stage(const char *text) { snprintf(stage_text, sizeof stage_text, "%s", text ? text : ""); }
void progress_set_subject(const char *text) { snprintf(subject_text, sizeof subject_text, "%s", text ? text : ""); }

void progress_span_begin(int64_t total)
{
    span.active = 1, span.drawn = 0;
    span.total = total > 0 ? total : 1, span.before = 0, span.size = span.total;
    span.start_seconds = seconds_now();
}

void progress_span_part(int64_t before, int64_t size) { span.before = before, span.size = size; }

void progress_span_end(void)
{
    if (span.active && span.drawn)
        fputc('\n', stderr);
    span.active = 0;
}

void progress_duration_text(double seconds, char *out, int size)
{
    long s = seconds > 0 ? (long)(seconds + 0.5) : 0;
    if (s < 60)
        snprintf(out, (size_t)size, "%ld s", s);
    else if (s < 3600)
        snprintf(out, (size_t)size, "%ld min %02ld s", s / 60, s % 60);
    else
        snprintf(out, (size_t)size, "%ld h %02ld min", s / 3600, s / 60 % 60);
}

/* The fraction of the whole done and the seconds since it began. */
static void whole_done(const progress *p, int64_t done, double *fraction, double *elapsed)
{
    double f = p->total > 0 ? (double)done / (double)p->total : 1.0;
    if (span.active)
        f = ((double)span.before + f * (double)span.size) / (double)span.total;
    *fraction = f < 1.0 ? f : 1.0;
    *elapsed = seconds_now() - (span.active ? span.start_seconds : p->start_seconds);
}

static void draw(const progress *p, int64_t done)
{
    enum { WIDTH = 30 };
    double fraction, elapsed;
    whole_done(p, done, &fraction, &elapsed);
    char bar[WIDTH + 1], took[32], eta[48] = "";
    for (int i = 0; i < WIDTH; ++i)
        bar[i] = i < (int)(fraction * WIDTH) ? '#' : '.';
    bar[WIDTH] = '\0';
    progress_duration_text(elapsed, took, sizeof took);
    if (fraction > 0.01 && fraction < 1.0) {
        char left[32];
        progress_duration_text(elapsed * (1.0 - fraction) / fraction, left, sizeof left);
        snprintf(eta, sizeof eta, ", ETA %s", left);
    }
    fprintf(stderr, "\r%s%s%s%s%s [%s] %5.1f%%  %s%s\033[K", stage_text, stage_text[0] ? " " : "", p->label,
            subject_text[0] ? " " : "", subject_text, bar, 100.0 * fraction, took, eta);
    fflush(stderr);
    span.drawn |= span.active;
}

void progress_begin(progress *p, const char *label, int64_t total)
{
    p->label = label;
    p->total = total;
    p->done = 0;
    p->drawn = 0;
    p->drawing = 0;
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
    /* Redraw at most every 1/200 of the work, by whichever thread crosses it
     * while no other draws. */
    int64_t step = p->total / 200 > 0 ? p->total / 200 : 1;
    int64_t drawn = __atomic_load_n(&p->drawn, __ATOMIC_RELAXED);
    if (done - drawn < step || __atomic_exchange_n(&p->drawing, 1, __ATOMIC_ACQUIRE))
        return;
    done = __atomic_load_n(&p->done, __ATOMIC_RELAXED); /* the latest: one drawer at a time, never backwards */
    __atomic_store_n(&p->drawn, done, __ATOMIC_RELAXED);
    draw(p, done);
    __atomic_store_n(&p->drawing, 0, __ATOMIC_RELEASE);
}

void progress_end(progress *p)
{
    if (!p->enabled)
        return;
    draw(p, __atomic_load_n(&p->done, __ATOMIC_RELAXED)); /* where it got to: all of it, or where it stopped */
    if (!span.active)
        fputc('\n', stderr);
}
