/* A technique as the command line sees it: the subcommands it adds to the
 * verbs (`gtlab approx NAME`, `fit`, `lut`, `check`, `bench`) and its
 * sections of `gtlab all`. Each technique defines one `technique` in its
 * folder's command-line face (techniques/<name>/<name>_cli.c);
 * techniques/CMakeLists.txt
 * lists them, one line each, cli/techniques.c is generated from it, and the
 * verbs, their --help and `gtlab all` are built from that list, so adding
 * a technique edits no verb (docs/adding-a-technique.md). The reference
 * quantities of `gtlab render` have their own registry one layer down
 * (raytracer/), since the raytracer must know them without the CLI. */
#ifndef GTLAB_CLI_TECHNIQUE_H
#define GTLAB_CLI_TECHNIQUE_H

#include <stddef.h>

#include "report/report_context.h" /* the context of a stage of `gtlab all` */
#include "cli/subcommands.h"

typedef enum { VERB_APPROX, VERB_FIT, VERB_LUT, VERB_CHECK, VERB_BENCH, VERB_RENDER, VERB_KIND_COUNT } technique_verb;

/* A section of `gtlab all`. */
typedef struct {
    const char *key;   /* --stages name */
    const char *title; /* progress line */
    int (*run)(report_context *ctx, gt_error *e);
    const char *writes; /* the folder below the output folder other stages read, or NULL */
    const char *needs;  /* the key of a stage whose `writes` folder this one reads, or NULL */
} all_stage;

/* A name a stage or subcommand went by before, and the one it has now: a
 * user's scripts keep the old one, and are told the new one (issue 43). */
typedef struct {
    const char *former, *name;
} technique_rename;

typedef struct {
    const char *name; /* the folder's name in kebab case: techniques/height_fog is "height-fog" */
    /* Per verb, a list ended by an entry with a NULL name; NULL: none. */
    const cli_subcommand *subcommands[VERB_KIND_COUNT];
    const all_stage *stages; /* ended by an entry with a NULL key; NULL: none */
    const technique_rename *renamed; /* ended by an entry with a NULL former; NULL: none */
} technique;

/* Defines technique_<id>: a technique that is one section of `gtlab all`
 * and nothing else (its stage's key, progress title, run and folder). */
#define GTLAB_STAGE_TECHNIQUE(id, key, title, run, writes)                                                   \
    static const all_stage id##_stages[] = {{key, title, run, writes, NULL}, {NULL, NULL, NULL, NULL, NULL}}; \
    const technique technique_##id = {.name = key, .stages = id##_stages}

/* A technique's tables written in place, the NULL terminator added:
 * .subcommands = {[VERB_LUT] = CLI_SUBCOMMANDS({"name", fn, "help"}, ...)}, .stages = ALL_STAGES({...}),
 * .renamed = TECHNIQUE_RENAMES({"old", "new"}, ...). */
#define TECHNIQUE_RENAMES(...) ((const technique_rename[]){__VA_ARGS__, {NULL, NULL}})
#define CLI_SUBCOMMANDS(...) ((const cli_subcommand[]){__VA_ARGS__, {NULL, NULL, NULL}})
#define ALL_STAGES(...) ((const all_stage[]){__VA_ARGS__, {NULL, NULL, NULL, NULL, NULL}})

/* A stage function `fn` that runs a study at the run's quality and renders
 * its section: with GTLAB_STUDY_STAGE, the study's types and functions are
 * named by its prefix (P_result, P_request, P_default_request(quality),
 * P_study(&ctx->study, &request, &result, e)); ..._NO_REQUEST names the
 * result type and the study, which takes no request. */
#define GTLAB_STUDY_STAGE(fn, prefix, section)                                                           \
    static int fn(report_context *ctx, gt_error *e)                                                     \
    {                                                                                                  \
        static prefix##_result r;                                                                      \
        prefix##_request rq = prefix##_default_request(ctx->study.quality);                            \
        return prefix##_study(&ctx->study, &rq, &r, e) != 0 ? -1 : section(ctx, &r, e);                \
    }
#define GTLAB_STUDY_STAGE_NO_REQUEST(fn, result_t, study_fn, section_fn)                         \
    static int fn(report_context *ctx, gt_error *e)                                       \
    {                                                                                    \
        static result_t r;                                                               \
        return study_fn(&ctx->study, &r, e) != 0 ? -1 : section_fn(ctx, &r, e);                \
    }

/* The registered techniques, in the report's order, ended by NULL. */
extern const technique *const gtlab_techniques[];

/* Every technique's subcommands of one verb, in registry order, into out
 * (at most capacity); returns their number. */
size_t technique_subcommands(technique_verb verb, cli_subcommand *out, size_t capacity);
/* Every stage of `gtlab all`, in registry order; returns their number. */
size_t technique_stages(const all_stage **out, size_t capacity);

/* The name a stage or subcommand has now that went by `former` before, or
 * NULL when no technique ever named one so. */
const char *technique_renamed(const char *former);

/* Runs `gtlab <verb> NAME ...` over the registry's subcommands of that verb. */
int technique_run_verb(technique_verb verb, const char *name, const char *usage, const char *kind, const char *noun,
                       int argc, char **argv);

#endif
