/* The report's summary table ("At a glance"): one row per technique that
 * ranks variants, registered by its section while `gtlab all` runs and
 * rendered once, at the top, by the writer (report_writer.c). A row holds
 * the best variant and its error, the runner-up and its error on the same
 * measure, and whether the gap between them is significant, taken from a
 * figure the section already has, never typed in:
 *
 *   significant      a paired difference d with standard error s over the
 *                    scenes has |d| > z s, z the 95% two-sided normal
 *                    quantile (claims_table.h's CLAIM_Z);
 *   not significant  |d| <= z s, or the gap is smaller than the
 *                    references' own noise floor (their halves' distance);
 *   above the noise floor  the gap exceeds that floor, with no interval;
 *   not computed     the section has no figure for it;
 *   no visible difference  the gap's interval lies within the measure's
 *                    visible margin (report_headline.margin), so the two are
 *                    equal to a viewer whatever the statistics say.
 *
 *   report_headline h = {.topic = "GGX sphere lights", .measure = "...",
 *                        .best = "Decima refit", .best_error = 0.149, ...};
 *   headline_from_difference(&h, d, s, "paired over 6 scenes");
 *   report_add_headline(ctx->doc, &h);   (the current section's anchor) */
#ifndef GTLAB_REPORT_HEADLINE_H
#define GTLAB_REPORT_HEADLINE_H

#include <stddef.h>

enum { HEADLINES_MAX = 48, HEADLINE_TEXT = 384 };

typedef enum {
    HEADLINE_NOT_COMPUTED,
    HEADLINE_SIGNIFICANT,
    HEADLINE_NOT_SIGNIFICANT,
    HEADLINE_ABOVE_NOISE_FLOOR,
    HEADLINE_NO_VISIBLE_DIFFERENCE
} headline_significance;

typedef struct {
    char topic[HEADLINE_TEXT];   /* the technique */
    char measure[HEADLINE_TEXT]; /* what the errors are: "mean DSSIM vs the Monte Carlo reference" */
    char best[HEADLINE_TEXT], runner_up[HEADLINE_TEXT];
    double best_error, runner_up_error;
    headline_significance significance;
    char basis[HEADLINE_TEXT];   /* the figure the verdict rests on */
    /* The smallest gap on this measure a viewer could see (a visibility
     * threshold, docs/claims-protocol.md), or 0 when none is stated. With
     * one, a gap whose whole interval lies within +-margin (or, against a
     * noise floor, a gap below it) is "no visible difference", however
     * significant; a significant gap smaller than the margin is not
     * called significant. Set it before the verdict functions below. */
    double margin;
    /* Not significant over paired cases: how many such cases would decide
     * it at 80% power if the gap and spread stay as observed (-1: none
     * would; 0: not computed). Said in `basis` too. */
    int cases_to_decide;
    int cases; /* how many paired cases the verdict has (0: not paired) */
    /* Below a noise floor: by what factor the references' samples would
     * have to grow for the floor to fall below the gap, if it falls as
     * 1/sqrt(samples) as Monte Carlo noise does (0: not computed). */
    double samples_factor_to_decide;
    /* The noise of the references the errors are measured against, as an
     * RMSE in the measure's units, and its budget: the most noise under
     * which the best figure reads within a quarter of the margin
     * (metrics/noise_corrected.h, noise_budget_for_rmse). Both 0: not
     * stated (a measure that is not an RMSE against a Monte Carlo
     * reference). Set by headline_state_reference_noise. */
    double reference_noise, noise_budget;
    char anchor[128];            /* the section's (set by report_add_headline) */
} report_headline;

/* Sets best and runner-up (and their errors) to the two lowest of
 * errors[0..count), NaNs left out (ties keep the earlier); -1 (h unchanged)
 * when fewer than two are numbers. */
int headline_rank(report_headline *h, int count, const char *const *labels, const double *errors);

/* headline_rank over each candidate's mean over `cases` per-case errors
 * (errors[i * cases + k]: candidate i, case k, e.g. a scene), then the
 * verdict of the paired difference runner-up - best over the cases, its
 * mean and standard error over the cases where both are numbers
 * (core/statistics/sample_mean.h; NaN cases left out); `over` names the cases ("6
 * scenes"). -1 (h unchanged) when fewer than two candidates have a mean. */
int headline_rank_paired(report_headline *h, int count, const char *const *labels, const double *errors, int cases,
                         const char *over);

/* After a ranking (headline_rank): the verdict of the paired difference
 * runner-up - best over per-case errors (errors[i * stride + k], case k <
 * cases of candidate i, labels[i] as ranked), as headline_rank_paired's. */
void headline_pair_cases(report_headline *h, int count, const char *const *labels, const double *errors, int stride,
                         int cases, const char *over);

/* The verdict of the mean d of `cases` paired differences with its own
 * standard error s: |d| > t s with Student's t quantile for cases - 1
 * degrees of freedom (core/statistics/sample_mean.h), not the normal 1.96, so a few
 * cases are not over-trusted (3 scenes: 4.30). Not significant, it says
 * how many cases would decide it (cases_to_decide). */
void headline_from_paired_cases(report_headline *h, double d, double s, int cases, const char *over);

/* The verdict of a paired difference d +- s (its mean and standard error);
 * `over` says what it is paired over. A NaN s leaves it not computed. */
void headline_from_difference(report_headline *h, double d, double s, const char *over);
/* The verdict of the gap |best - runner-up| against a noise floor on the
 * same measure (the distance between two halves of the reference). */
void headline_from_noise_floor(report_headline *h, double floor);

/* The margin's verdict on a gap d whose interval is d -+ w (w = 0: no
 * interval), after one of the verdicts above (they call it themselves);
 * nothing when h->margin is 0. */
void headline_apply_margin(report_headline *h, double d, double w);

/* For a row whose errors are RMSEs against Monte Carlo references of
 * noise RMSE `noise` (sqrt of the mean squared standard error over their
 * pixels and cases), after its ranking and margin: sets reference_noise and
 * noise_budget and appends to the basis whether the references met it, and
 * if not by how much they inflate the best figure. The verdict stands
 * either way: the noise adds the same mean variance to both sides' squared
 * errors, so sqrt(a^2 + n^2) - sqrt(b^2 + n^2) keeps the sign of a - b and
 * shrinks it; it can hide a visible gap, never reverse a ranking. */
void headline_state_reference_noise(report_headline *h, double noise);
/* "noise RMSE 0.012, within its budget 0.015" or "noise RMSE 0.06, over
 * its budget 0.015: figures near 0.12 read up to 0.014 high": a reference
 * of noise RMSE `noise` against the budget of a measured RMSE `figure`
 * (its noise taken out first) with visible margin `margin`. */
void noise_budget_phrase(double noise, double figure, double margin, char *out, size_t size);
/* Whether h's references are stated and missed their noise budget. */
int headline_missed_noise_budget(const report_headline *h);

/* A row as a JSON object of its fields (a stage's part, report/report_part.h;
 * its doubles exact, core/files/json_file.h), and back: 0, or -1 when o
 * lacks a field or holds a wrong type. The anchor is not kept:
 * report_add_headline sets it. */
struct cJSON *headline_to_json(const report_headline *h);
int headline_from_json(const struct cJSON *o, report_headline *h);

/* "significant at 95%", "not significant at this quality", "above the
 * noise floor (no interval)", "not computed". */
const char *headline_significance_name(headline_significance s);

/* The sentence the summary opens with (issue 46 item 2): how many
 * rankings are decided (significant and visible), how many are equal to a
 * viewer, and, for each undecided one, what would decide it (cases_to_decide
 * or samples_factor_to_decide), then which rows' references missed their
 * noise budget. Empty for no rows; truncated to size. */
void headlines_opening(const report_headline *rows, int count, char *out, size_t size);

/* The summary table as Markdown and HTML (malloc'd, NULL-terminated; both
 * NULL when out of memory); an empty string for no rows. */
int headlines_render(const report_headline *rows, int count, char **md, char **html);

#endif
