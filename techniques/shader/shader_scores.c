/* The project's shaders and plug-ins by quantity (shader_scores.h). */
#include "shader/shader_scores.h"

#include <stdlib.h>
#include <string.h>

#include "gpu/function_shader.h"
#include "gpu/shader_compiler.h"
#include "multibounce/multibounce_score.h"
#include "plugins/plugin_loader.h"
#include "multibounce/multibounce_score.h"
#include "specular_occlusion/specular_occlusion_score.h"
#include "project/project_file.h"

enum { QUANTITY_MB, QUANTITY_SO, QUANTITIES };

static const function_score_quantity *const kQuantities[QUANTITIES] = {&multibounce_scored_quantity,
                                                                       &specular_occlusion_scored_quantity};

typedef struct {
    const char *functions[PROJECT_MAX_FILES], *plugins[PROJECT_MAX_FILES];
    int function_count, plugin_count;
} quantity_files;

/* A function file into the list of each quantity it defines. */
static int sort_function(const char *path, quantity_files q[QUANTITIES], gt_error *e)
{
    char *text;
    if (gpu_read_source(path, &text, e) != 0)
        return -1;
    int found = 0;
    for (int k = 0; k < QUANTITIES; ++k)
        if (gpu_function_defines(kQuantities[k]->function, text))
            q[k].functions[q[k].function_count++] = path, found = 1;
    free(text);
    return found ? 0
                 : gt_error_set(e, path, "defines neither %s nor %s (the function contracts: docs/shaders.md)",
                                kQuantities[0]->function->name, kQuantities[1]->function->name);
}

/* A plug-in into the list of each quantity it exports an entry point of. */
static int sort_plugin(const char *path, quantity_files q[QUANTITIES], gt_error *e)
{
    gtlab_plugin p;
    if (plugin_open(path, &p, e) != 0)
        return -1;
    for (int k = 0; k < QUANTITIES; ++k)
        if (plugin_exports(&p, kQuantities[k]->plugin_symbol))
            q[k].plugins[q[k].plugin_count++] = path;
    plugin_close(&p);
    return 0;
}

int shader_scores_project(const study_context *ctx, shader_scores_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    const study_project *p = ctx->project;
    if (!p)
        return 0;
    quantity_files q[QUANTITIES];
    memset(q, 0, sizeof q);
    int rc = 0;
    for (int i = 0; i < p->shader_count && rc == 0; ++i)
        rc = sort_function(p->shaders[i], q, e);
    for (int i = 0; i < p->plugin_count && rc == 0; ++i)
        rc = sort_plugin(p->plugins[i], q, e);
    const quantity_files *mb = &q[QUANTITY_MB], *so = &q[QUANTITY_SO];
    if (rc == 0)
        rc = multibounce_score_project(ctx, mb->functions, mb->function_count, mb->plugins, mb->plugin_count,
                                       &out->multibounce, e);
    if (rc == 0)
        rc = specular_occlusion_score_project(ctx, so->functions, so->function_count, so->plugins, so->plugin_count,
                                              &out->specular_occlusion, e);
    return rc;
}

int shader_score(const shader_score_request *rq, function_score_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    if (rq->quantity && strcmp(rq->quantity, SO_SCORE_QUANTITY) == 0) {
        specular_occlusion_score_request so = {rq->references, rq->reference_count, rq->aos, rq->ao_count, rq->files};
        return specular_occlusion_score(&so, out, e);
    }
    if (rq->quantity && strcmp(rq->quantity, "multibounce") != 0)
        return gt_error_set(e, "--quantity", "'%s': gtlab scores multibounce and %s functions (so far)", rq->quantity,
                            SO_SCORE_QUANTITY);
    multibounce_score_request mb = {rq->references, rq->reference_count, rq->files};
    return multibounce_score(&mb, out, e);
}
