#include "project/project_file.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/files/atomic_file.h"
#include "core/files/input_file.h"
#include "core/files/json_file.h"
#include "core/files/run_inputs.h"
#include "scene/builtin_scenes.h"
#include "core/reference_schema.h"

enum { PROJECT_FILE_MAX = 1 << 20 };

/* What every reader below needs: the file, its folder and the error. */
typedef struct {
    const char *path;
    char dir[STUDY_SCENE_PATH_MAX];
    study_project_stage_known known;
    gt_error *e;
} reader;

static int fail(const reader *r, const char *where, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int fail(const reader *r, const char *where, const char *fmt, ...)
{
    char problem[768];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(problem, sizeof problem, fmt, ap);
    va_end(ap);
    return gt_error_set(r->e, r->path, "%s: %s", where, problem);
}

/* The error already in r->e, prefixed with the file and the JSON path. */
static int fail_again(const reader *r, const char *where)
{
    char problem[sizeof r->e->message];
    snprintf(problem, sizeof problem, "%s", r->e->message);
    return fail(r, where, "%s", problem);
}

/* The JSON gate, then cJSON; the root must be an object. */
static cJSON *parse(const char *path, gt_error *e)
{
    return json_file_read_object(path, PROJECT_FILE_MAX, "project file larger than 1 MiB", "a gtlab project file", e);
}

/* Every key of o is in `allowed` (NULL-ended) or starts with '_' (a comment). */
static int check_keys(const reader *r, const cJSON *o, const char *where, const char *const *allowed)
{
    for (const cJSON *c = o->child; c; c = c->next) {
        int ok = c->string[0] == '_';
        for (int i = 0; allowed[i] && !ok; ++i)
            ok = strcmp(c->string, allowed[i]) == 0;
        if (!ok) {
            gt_quoted q;
            return fail(r, where, "unknown key '%s' (keys starting with '_' are comments)", gt_quote(c->string, &q));
        }
    }
    return 0;
}

/* A path of the file made usable from the working folder: builtin:NAME and
 * absolute paths as they are, others relative to the file's folder. */
static int resolve(const reader *r, const char *where, const char *value, char *out, size_t size)
{
    int n = strncmp(value, "builtin:", 8) == 0 || value[0] == '/' || !r->dir[0]
                ? snprintf(out, size, "%s", value)
                : snprintf(out, size, "%s/%s", r->dir, value);
    return n > 0 && (size_t)n < size ? 0 : fail(r, where, "empty or longer than %zu characters", size - 1);
}

/* A string member (NULL when absent); -1 when present but not a string. */
static int member_string(const reader *r, const cJSON *o, const char *key, const char *where, const char **out)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    *out = cJSON_IsString(v) ? v->valuestring : NULL;
    return v && !cJSON_IsString(v) ? fail(r, where, "'%s' must be a string", key) : 0;
}

/* A file that must exist and be a regular file: an input of the run
 * (core/files/run_inputs.h), which no output may replace. */
static int existing_file(const reader *r, const char *where, const char *value, char *out, size_t size)
{
    struct stat st;
    if (resolve(r, where, value, out, size) != 0)
        return -1;
    if (stat(out, &st) != 0)
        return fail(r, where, "%s: %s", out, strerror(errno));
    if (input_file_check(out, NULL, r->e) != 0) /* a folder, a device, a FIFO: said so */
        return fail_again(r, where);
    char given_as[STUDY_SCENE_PATH_MAX];
    snprintf(given_as, sizeof given_as, "%s: %s:", r->path, where);
    run_inputs_note(out, given_as);
    return 0;
}

/* "gltf": a camera index (a whole number) or a camera name (a string). */
static int read_gltf_camera(const reader *r, const cJSON *v, const char *where, study_scene_entry *x)
{
    if (cJSON_IsString(v)) {
        size_t n = strlen(v->valuestring);
        if (n == 0 || n >= sizeof x->gltf_camera_name)
            return fail(r, where, "a camera name of 1 to %zu characters expected", sizeof x->gltf_camera_name - 1);
        memcpy(x->gltf_camera_name, v->valuestring, n + 1);
        return 0;
    }
    if (!cJSON_IsNumber(v) || v->valuedouble != (double)(int)v->valuedouble || v->valuedouble < 0 ||
        v->valuedouble > 65535)
        return fail(r, where, "a camera index (0, 1, ...) or a camera name expected");
    x->gltf_camera = (int)v->valuedouble;
    return 0;
}

/* One camera: {} the scene's own, {"gltf": index or name}, {"file": camera JSON}. */
static int read_camera(const reader *r, const cJSON *c, const char *where, study_scene_entry *x, const char **label)
{
    static const char *const keys[] = {"gltf", "file", "label", NULL};
    char at[320];
    if (!cJSON_IsObject(c))
        return fail(r, where, "a camera is an object: {}, {\"gltf\": 0} or {\"file\": \"camera.json\"}");
    const cJSON *gltf = cJSON_GetObjectItemCaseSensitive(c, "gltf");
    const char *file;
    if (check_keys(r, c, where, keys) != 0 || member_string(r, c, "file", where, &file) != 0 ||
        member_string(r, c, "label", where, label) != 0)
        return -1;
    if (gltf && file)
        return fail(r, where, "give 'gltf' or 'file', not both");
    snprintf(at, sizeof at, "%s.%s", where, gltf ? "gltf" : "file");
    if (gltf)
        return read_gltf_camera(r, gltf, at, x);
    return file ? existing_file(r, at, file, x->camera_json, sizeof x->camera_json) : 0;
}

/* The label a scene gets without one: its file name up to the first '.', or
 * its built-in name. */
static void default_label(const char *path, char *label, size_t size)
{
    const char *slash = strrchr(path, '/');
    const char *name = strncmp(path, "builtin:", 8) == 0 ? path + 8 : slash ? slash + 1 : path;
    snprintf(label, size, "%.*s", (int)strcspn(name, "."), name);
}

/* The scene file (or built-in scene) exists; its label, given or the default. */
static int read_scene_path(const reader *r, const cJSON *o, const char *where, study_scene_entry *x, char *label,
                           size_t label_size)
{
    const char *path, *given;
    char at[256];
    snprintf(at, sizeof at, "%s.path", where);
    if (member_string(r, o, "path", where, &path) != 0 || member_string(r, o, "label", where, &given) != 0)
        return -1;
    if (!path)
        return fail(r, where, "'path' (a .gltf/.glb file or builtin:NAME) is missing");
    int builtin = strncmp(path, "builtin:", 8) == 0;
    if (builtin && !builtin_scene_find(path + 8))
        return fail(r, at, "no built-in scene '%s' (see 'gtlab scene list')", path + 8);
    if (builtin ? resolve(r, at, path, x->spec, sizeof x->spec) : existing_file(r, at, path, x->spec, sizeof x->spec))
        return -1;
    if (given)
        snprintf(label, label_size, "%s", given);
    else
        default_label(path, label, label_size);
    char what[512];
    snprintf(what, sizeof what, "%s: %s.label", r->path, where);
    return study_scene_label_check(label, what, r->e);
}

/* The entry loads and its camera is valid: a bad scene stops the run before any work. */
static int check_loads(const reader *r, const study_scene_entry *x, const char *where)
{
    scene s;
    camera cam;
    if (study_scene_view(x, 0, 0, &s, &cam, r->e) != 0)
        return fail_again(r, where);
    scene_free(&s);
    return 0;
}

/* Camera k of a scene as a list entry: labelled by the scene alone when it
 * is the scene's only camera, else "<scene>-<camera label or cam<k>>". */
static int add_camera(const reader *r, const cJSON *c, const char *where, study_scene_entry x, const char *label, int k,
                      int cameras, study_project *p)
{
    const char *own = NULL;
    char what[512], composed[256];
    if (c && read_camera(r, c, where, &x, &own) != 0)
        return -1;
    if (cameras > 1 && own)
        snprintf(composed, sizeof composed, "%s-%s", label, own);
    else if (cameras > 1)
        snprintf(composed, sizeof composed, "%s-cam%d", label, k);
    snprintf(what, sizeof what, "%s: %s", r->path, where);
    if (study_scene_label_check(cameras > 1 ? composed : label, what, r->e) != 0)
        return -1;
    snprintf(x.label, sizeof x.label, "%.47s", cameras > 1 ? composed : label);
    return study_scene_list_add(&p->scenes, &x, what, r->e) != 0 ? -1 : check_loads(r, &x, where);
}

/* One scene: {"path": ..., "label": ..., "cameras": [...]} (no cameras: its own). */
static int read_scene(const reader *r, const cJSON *o, const char *where, study_project *p)
{
    static const char *const keys[] = {"path", "label", "cameras", NULL};
    study_scene_entry x = {.gltf_camera = -1};
    char label[256], at[256];
    if (!cJSON_IsObject(o))
        return fail(r, where, "a scene is an object with 'path', 'label' and 'cameras'");
    if (check_keys(r, o, where, keys) != 0 || read_scene_path(r, o, where, &x, label, sizeof label) != 0)
        return -1;
    const cJSON *cams = cJSON_GetObjectItemCaseSensitive(o, "cameras");
    if (cams && (!cJSON_IsArray(cams) || cJSON_GetArraySize(cams) == 0))
        return fail(r, where, "'cameras' must be a non-empty array");
    if (!cams)
        return add_camera(r, NULL, where, x, label, 0, 1, p);
    int k = 0, count = cJSON_GetArraySize(cams);
    for (const cJSON *c = cams->child; c; c = c->next, ++k) {
        snprintf(at, sizeof at, "%s.cameras[%d]", where, k);
        if (add_camera(r, c, at, x, label, k, count, p) != 0)
            return -1;
    }
    return 0;
}

/* "quality": "preview" or "production". */
static int read_quality(const reader *r, const cJSON *root, study_project *p)
{
    const char *q;
    if (member_string(r, root, "quality", "quality", &q) != 0)
        return -1;
    p->quality = -1;
    for (int i = 0; q && i < STUDY_QUALITY_COUNT; ++i)
        if (strcmp(q, study_quality_name((study_quality)i)) == 0)
            p->quality = i;
    return q && p->quality == -1 ? fail(r, "quality", "'preview' or 'production' expected") : 0;
}

/* An array of strings (absent: empty), each handed to `take`. */
static int read_strings(const reader *r, const cJSON *root, const char *key, study_project *p,
                        int (*take)(const reader *, const char *, const char *, study_project *))
{
    const cJSON *a = cJSON_GetObjectItemCaseSensitive(root, key);
    if (a && !cJSON_IsArray(a))
        return fail(r, key, "an array expected");
    char at[128];
    int k = 0;
    for (const cJSON *v = a ? a->child : NULL; v; v = v->next, ++k) {
        snprintf(at, sizeof at, "%s[%d]", key, k);
        if (!cJSON_IsString(v))
            return fail(r, at, "a string expected");
        if (take(r, at, v->valuestring, p) != 0)
            return -1;
    }
    return 0;
}

static int take_stage(const reader *r, const char *at, const char *key, study_project *p)
{
    gt_quoted q;
    const char *now = NULL;
    if (key[0] == '\0' || strchr(key, ',') || (r->known && !r->known(key, &now)))
        return now ? fail(r, at, "stage '%s' is now '%s'", gt_quote(key, &q), now)
                   : fail(r, at, "unknown stage '%s' (see 'gtlab all --help')", gt_quote(key, &q));
    size_t n = strlen(p->stages);
    if (n + strlen(key) + 2 > sizeof p->stages)
        return fail(r, at, "the stage list is longer than %zu characters", sizeof p->stages - 2);
    snprintf(p->stages + n, sizeof p->stages - n, "%s%s", n ? "," : "", key);
    return 0;
}

/* A shader (function file) or plug-in file: recorded, scored by the stage shader-scores. */
static int take_file(const reader *r, const char *at, const char *value, char (*files)[STUDY_SCENE_PATH_MAX],
                     int *count)
{
    if (*count == PROJECT_MAX_FILES)
        return fail(r, at, "more than %d files", PROJECT_MAX_FILES);
    return existing_file(r, at, value, files[*count], STUDY_SCENE_PATH_MAX) != 0 ? -1 : (++*count, 0);
}

static int take_shader(const reader *r, const char *at, const char *value, study_project *p)
{
    return take_file(r, at, value, p->shaders, &p->shader_count);
}

static int take_plugin(const reader *r, const char *at, const char *value, study_project *p)
{
    return take_file(r, at, value, p->plugins, &p->plugin_count);
}

/* A screen shader's "params": {"name": number, ...}, as "name=value". */
static int read_params(const reader *r, const cJSON *o, const char *where, study_screen_shader *x)
{
    const cJSON *params = cJSON_GetObjectItemCaseSensitive(o, "params");
    if (params && !cJSON_IsObject(params))
        return fail(r, where, "'params' must be an object of numbers, {\"radius\": 1.0}");
    for (const cJSON *v = params ? params->child : NULL; v; v = v->next) {
        if (v->string[0] == '_')
            continue; /* a comment */
        gt_quoted q;
        if (!cJSON_IsNumber(v))
            return fail(r, where, "params.%s: a number expected", gt_quote(v->string, &q));
        if (x->param_count == PROJECT_MAX_PARAMS)
            return fail(r, where, "params: more than %d parameters", PROJECT_MAX_PARAMS);
        snprintf(x->params[x->param_count++], PROJECT_PARAM_TEXT, "%.60s=%.17g", v->string, v->valuedouble);
    }
    return 0;
}

int study_screen_shader_prepare(const study_screen_shader *s, screen_shader_program *out, gt_error *e)
{
    const char *params[PROJECT_MAX_PARAMS];
    for (int i = 0; i < s->param_count; ++i)
        params[i] = s->params[i];
    return screen_shader_prepare(s->path, params, s->param_count, CH_AO, out, e);
}

/* One screen shader: {"path": ..., "quantity": "ao", "params": {...}}, compiled now. */
static int read_screen_shader(const reader *r, const cJSON *o, const char *where, study_project *p)
{
    static const char *const keys[] = {"path", "quantity", "params", NULL};
    study_screen_shader *x = &p->screen_shaders[p->screen_shader_count];
    const char *path, *quantity;
    char at[160];
    snprintf(at, sizeof at, "%s.path", where);
    if (!cJSON_IsObject(o))
        return fail(r, where, "a screen shader is an object: {\"path\": \"my_gtao.hlsl\", \"params\": {...}}");
    if (check_keys(r, o, where, keys) != 0 || member_string(r, o, "path", where, &path) != 0 ||
        member_string(r, o, "quantity", where, &quantity) != 0 || read_params(r, o, where, x) != 0)
        return -1;
    if (!path)
        return fail(r, where, "'path' (a .glsl or .hlsl file) is missing");
    gt_quoted q;
    if (quantity && strcmp(quantity, "ao") != 0)
        return fail(r, where, "quantity '%s': only 'ao' (ambient occlusion, ao.V) is scored", gt_quote(quantity, &q));
    screen_shader_program program;
    if (existing_file(r, at, path, x->path, sizeof x->path) != 0)
        return -1;
    if (study_screen_shader_prepare(x, &program, r->e) != 0)
        return fail_again(r, at);
    screen_shader_program_free(&program);
    return ++p->screen_shader_count, 0;
}

/* "screen_shaders": an array of screen shaders (absent: none). */
static int read_screen_shaders(const reader *r, const cJSON *root, study_project *p)
{
    const cJSON *a = cJSON_GetObjectItemCaseSensitive(root, "screen_shaders");
    if (a && !cJSON_IsArray(a))
        return fail(r, "screen_shaders", "an array expected");
    char at[64];
    int k = 0;
    for (const cJSON *o = a ? a->child : NULL; o; o = o->next, ++k) {
        snprintf(at, sizeof at, "screen_shaders[%d]", k);
        if (k == PROJECT_MAX_FILES)
            return fail(r, at, "more than %d files", PROJECT_MAX_FILES);
        if (read_screen_shader(r, o, at, p) != 0)
            return -1;
    }
    return 0;
}

/* "scenes": a non-empty array (absent: the built-in scenes). */
static int read_scenes(const reader *r, const cJSON *root, study_project *p)
{
    const cJSON *a = cJSON_GetObjectItemCaseSensitive(root, "scenes");
    if (a && (!cJSON_IsArray(a) || cJSON_GetArraySize(a) == 0))
        return fail(r, "scenes", "a non-empty array of scenes expected");
    char at[64];
    int k = 0;
    for (const cJSON *o = a ? a->child : NULL; o; o = o->next, ++k) {
        snprintf(at, sizeof at, "scenes[%d]", k);
        if (read_scene(r, o, at, p) != 0)
            return -1;
    }
    return 0;
}

static int read_settings(const reader *r, const cJSON *root, study_project *p)
{
    static const char *const keys[] = {"scenes", "stages", "quality", "output", "shaders", "plugins",
                                       "screen_shaders", NULL};
    const char *output;
    if (check_keys(r, root, "(top level)", keys) != 0 || read_quality(r, root, p) != 0 ||
        member_string(r, root, "output", "output", &output) != 0 ||
        (output && resolve(r, "output", output, p->output_dir, sizeof p->output_dir) != 0))
        return -1;
    if (read_strings(r, root, "stages", p, take_stage) != 0 || read_strings(r, root, "shaders", p, take_shader) != 0 ||
        read_strings(r, root, "plugins", p, take_plugin) != 0 || read_screen_shaders(r, root, p) != 0)
        return -1;
    return read_scenes(r, root, p);
}

int study_project_read(const char *path, study_project_stage_known known, study_project *p, gt_error *e)
{
    memset(p, 0, sizeof *p);
    reader r = {path, "", known, e};
    const char *slash = strrchr(path, '/');
    if (slash)
        snprintf(r.dir, sizeof r.dir, "%.*s", (int)(slash - path), path);
    if (slash == path)
        snprintf(r.dir, sizeof r.dir, "/");
    cJSON *root = parse(path, e);
    int rc = root ? read_settings(&r, root, p) : -1;
    cJSON_Delete(root);
    return rc;
}

void study_project_apply(const study_project *p, study_context *ctx, const char **stage_list)
{
    const int given = p && p->quality >= 0;
    ctx->scenes = p && p->scenes.count ? &p->scenes : NULL;
    ctx->project = p;
    if ((int)ctx->quality < 0)
        ctx->quality = given ? (study_quality)p->quality : QUALITY_PREVIEW;
    if (!ctx->output_dir)
        ctx->output_dir = p && p->output_dir[0] ? p->output_dir : "results";
    if (!*stage_list && p && p->stages[0])
        *stage_list = p->stages;
}

static const char example[] =
    "{\n"
    "  \"_comment\": \"A gtlab project (docs/design.md, 'Project file'; schema: docs/gtlab.schema.json). Keys starting "
    "with '_' are comments. Paths are relative to this file's folder. 'gtlab all --project gtlab.json' runs the stages "
    "on these scenes; its --quality, --stages and -o override quality, stages and output.\",\n"
    "  \"quality\": \"preview\",\n"
    "  \"_stages\": \"Stage names as 'gtlab all --help' lists them; leave 'stages' out for every stage. The "
    "scene-driven ones: ao, gtao, gtao-shortcuts, specular-occlusion, environment; the others keep their own "
    "purpose-built scenes.\",\n"
    "  \"stages\": [\"ao\", \"gtao\"],\n"
    "  \"output\": \"gtlab-results\",\n"
    "  \"scenes\": [\n"
    "    {\n"
    "      \"_comment\": \"path: a .gltf or .glb file ('gtlab scene write sphere-on-plane -o mine.glb' makes one) "
    "or builtin:NAME. label: names the scene's rows and files (letters, digits, '_', '.', '-'); default: the file "
    "name up to its first '.'.\",\n"
    "      \"path\": \"builtin:sphere-on-plane\",\n"
    "      \"label\": \"my-scene\",\n"
    "      \"_cameras\": \"One report row per camera: {} the scene's own camera, {\\\"gltf\\\": 0} or "
    "{\\\"gltf\\\": \\\"Name\\\"} a camera of the glTF file, {\\\"file\\\": \\\"camera.json\\\"} a "
    "camera JSON file as 'gtlab render --camera' takes it. With two or more cameras each row is labelled "
    "<label>-<camera label> (default cam0, cam1, ...).\",\n"
    "      \"cameras\": [{}]\n"
    "    }\n"
    "  ],\n"
    "  \"_shaders\": \"GLSL/HLSL multi-bounce functions (docs/shaders.md, 'Functions') and C plug-ins "
    "(core/plugin_abi.h), scored beside gtlab's own by the stage shader-scores on the multibounce stage's "
    "references.\",\n"
    "  \"shaders\": [],\n"
    "  \"plugins\": [],\n"
    "  \"_screen_shaders\": \"Screen-space AO shaders (docs/shaders.md, 'Screen-space shaders'), e.g. {\\\"path\\\": "
    "\\\"my_gtao.hlsl\\\", \\\"params\\\": {\\\"radius\\\": 1.0}}: compiled when the project is read, scored beside "
    "gtlab's GTAO by the stage screen-shaders on the ao stage's references.\",\n"
    "  \"screen_shaders\": []\n"
    "}\n";

const char *study_project_example(void) { return example; }

int study_project_write_example(const char *path, gt_error *e)
{
    struct stat st;
    if (stat(path, &st) == 0)
        return gt_error_set(e, path, "already exists: not overwritten (remove it, or give another -o)");
    return atomic_write_text(path, example, e);
}
