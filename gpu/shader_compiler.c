#define _GNU_SOURCE
#include "gpu/shader_compiler.h"

#include <shaderc/shaderc.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "core/files/input_file.h"
#include "core/isolated_call.h"

gpu_source_language gpu_source_language_of(const char *path)
{
    size_t n = strlen(path);
    return n >= 5 && strcasecmp(path + n - 5, ".hlsl") == 0 ? GPU_SOURCE_HLSL : GPU_SOURCE_GLSL;
}

/* The line of `log` holding the first "error", or its first line. */
static const char *first_error_line(const char *log, size_t *length)
{
    const char *at = strstr(log, "error");
    const char *start = at ? at : log;
    while (start > log && start[-1] != '\n')
        --start;
    *length = strcspn(start, "\n");
    return start;
}

int gpu_compile_error_line(const char *log, const char *name, gt_error *e)
{
    size_t length;
    const char *line = first_error_line(log ? log : "", &length);
    const char *mark = strstr(line, ": error");
    if (!mark || (size_t)(mark - line) >= length || mark - line >= 512)
        return gt_error_set(e, name, "shader compilation failed: %.*s", (int)length, line);
    /* "f.glsl:12: error: 'x' : undeclared identifier": subject "f.glsl:12". */
    char subject[512];
    snprintf(subject, sizeof subject, "%.*s", (int)(mark - line), line);
    const char *problem = mark + 2;
    return gt_error_set(e, subject, "%.*s", (int)(length - (size_t)(problem - line)), problem);
}

/* The bytes of a successful result, copied out of shaderc's. */
static int copy_result(shaderc_compilation_result_t result, const char *name, void **bytes, size_t *size,
                       gt_error *e)
{
    *size = shaderc_result_get_length(result);
    *bytes = malloc(*size ? *size : 1);
    if (!*bytes)
        return gt_error_set(e, name, "out of memory for %zu bytes of SPIR-V", *size);
    memcpy(*bytes, shaderc_result_get_bytes(result), *size);
    return 0;
}

/* An #include, "f.inc" or <f.inc>, is the file f.inc beside the file that
 * includes it (its directory; the working directory for a name without
 * one). Nesting deeper than 32 is an error, not an endless include loop. */
static shaderc_include_result *resolve_include(void *user, const char *requested, int type, const char *requesting,
                                               size_t depth)
{
    enum { MAX_DEPTH = 32 };
    (void)user, (void)type;
    const char *slash = strrchr(requesting, '/');
    int dir = slash ? (int)(slash - requesting + 1) : 0;
    char *path = NULL, *text = NULL;
    gt_error e = {{0}};
    if (requested[0] == '/')
        dir = 0;
    if (asprintf(&path, "%.*s%s", dir, requesting, requested) < 0)
        return NULL;
    if (depth > MAX_DEPTH) /* a failed inclusion: no name, the message as its content */
        path[0] = '\0', text = strdup("includes nested more than 32 deep (an include loop?)");
    else if (gpu_read_source(path, &text, &e) != 0)
        path[0] = '\0', text = strdup(e.message);
    shaderc_include_result *r = calloc(1, sizeof *r);
    if (!r || !text)
        return free(r), free(path), free(text), NULL;
    *r = (shaderc_include_result){path, strlen(path), text, strlen(text), NULL};
    return r;
}

static void release_include(void *user, shaderc_include_result *r)
{
    (void)user;
    if (r)
        free((char *)r->source_name), free((char *)r->content), free(r);
}

/* Vulkan 1.1 SPIR-V, optimised for performance; HLSL with its own front end;
 * #include resolved beside the including file. */
static shaderc_compile_options_t compile_options(gpu_source_language language)
{
    shaderc_compile_options_t options = shaderc_compile_options_initialize();
    if (!options)
        return NULL;
    shaderc_compile_options_set_source_language(
        options, language == GPU_SOURCE_HLSL ? shaderc_source_language_hlsl : shaderc_source_language_glsl);
    shaderc_compile_options_set_target_env(options, shaderc_target_env_vulkan, shaderc_env_version_vulkan_1_1);
    shaderc_compile_options_set_optimization_level(options, shaderc_optimization_level_performance);
    shaderc_compile_options_set_include_callbacks(options, resolve_include, release_include, NULL);
    return options;
}

/* Whether the compiler warned that it found no entry point: glslang then
 * (HLSL, where main may be a mere prototype or --entry names no function)
 * makes an empty one, a shader that writes nothing. */
static int entry_missing(shaderc_compilation_result_t result)
{
    const char *log = shaderc_result_get_error_message(result);
    return shaderc_result_get_num_warnings(result) > 0 && log && strstr(log, "Entry point not found") != NULL;
}

/* One compilation as the child process runs it (compile_isolated). */
typedef struct {
    const char *source, *name, *entry;
    gpu_source_language language;
} compile_job;

/* shaderc on one job, in this process: the SPIR-V's bytes, or -1 with e =
 * the compiler's first error line. */
static int compile_here(const void *context, void **bytes, size_t *size, gt_error *e)
{
    const compile_job *job = context;
    shaderc_compiler_t compiler = shaderc_compiler_initialize();
    shaderc_compile_options_t options = compile_options(job->language);
    if (!compiler || !options) {
        shaderc_compile_options_release(options);
        shaderc_compiler_release(compiler);
        return gt_error_set(e, job->name, "cannot start the shaderc compiler");
    }
    shaderc_compilation_result_t result = shaderc_compile_into_spv(
        compiler, job->source, strlen(job->source), shaderc_compute_shader, job->name, job->entry, options);
    int rc = shaderc_result_get_compilation_status(result) != shaderc_compilation_status_success
                 ? gpu_compile_error_line(shaderc_result_get_error_message(result), job->name, e)
             : entry_missing(result) ? gt_error_set(e, job->name, "no function %s with a body: nothing to run (a "
                                                                  "function header without its { } body is not one)",
                                                    job->entry)
                                     : copy_result(result, job->name, bytes, size, e);
    shaderc_result_release(result);
    shaderc_compile_options_release(options);
    shaderc_compiler_release(compiler);
    return rc;
}

/* The compiler's CPU time per source: shaderc compiles a screen shader in
 * well under a second, so a minute means it is looping. */
enum { GPU_COMPILE_CPU_SECONDS = 60 };

/* glslang crashes on some malformed source (issue 41: an HLSL function
 * header without its body, followed by a global's name, is a null read in
 * TParseContextBase::growGlobalUniformBlock), so it runs in a child process
 * (core/isolated_call.h): its crash is this one line, never gtlab's. */
static int compile_isolated(const compile_job *job, void **bytes, size_t *size, gt_error *e)
{
    char death[128];
    int rc = isolated_call(compile_here, job, job->name, GPU_COMPILE_CPU_SECONDS, bytes, size, death, sizeof death, e);
    if (rc != ISOLATED_DIED)
        return rc;
    return gt_error_set(e, job->name,
                        "the shader compiler died on this source (glslang, %s); check its syntax: a function "
                        "header without its { } body is one known cause",
                        death);
}

int gpu_compile_compute(const char *source, const char *name, gpu_source_language language, const char *entry,
                        gpu_spirv *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    entry = entry ? entry : "main";
    if (strlen(entry) >= sizeof out->entry)
        return gt_error_set(e, name, "entry point name longer than %zu characters", sizeof out->entry - 1);
    if (language == GPU_SOURCE_GLSL && strcmp(entry, "main") != 0)
        return gt_error_set(e, name, "a GLSL shader's entry point is main, not %s", entry);
    compile_job job = {source, name, entry, language};
    void *bytes = NULL;
    size_t size = 0;
    if (compile_isolated(&job, &bytes, &size, e) != 0)
        return -1;
    out->words = bytes;
    out->count = size / sizeof(uint32_t);
    snprintf(out->entry, sizeof out->entry, "%s", entry);
    return 0;
}

void gpu_spirv_free(gpu_spirv *spirv)
{
    free(spirv->words);
    memset(spirv, 0, sizeof *spirv);
}

int gpu_read_source(const char *path, char **text, gt_error *e)
{
    enum { MAX_BYTES = 4 << 20 };
    size_t n;
    if (input_file_read(path, MAX_BYTES, "larger than 4 MiB: not a shader", text, &n, e) != 0)
        return -1;
    if (memchr(*text, '\0', n)) {
        free(*text);
        *text = NULL;
        return gt_error_set(e, path, "holds a NUL byte: not a shader's text");
    }
    return 0;
}
