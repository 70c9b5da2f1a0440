/* Fuzz target "shader": a compute shader's text through the compiler every
 * verb uses (gpu/shader_compiler.h: shaderc, glslang's GLSL and HLSL front
 * ends, the #include resolver), the same crash-proof path as `gtlab shader
 * run`: glslang runs in a child process, and a crash there must come back
 * as one error line, never kill this process (issue 41). Text holding
 * "#version" is GLSL, anything else HLSL. The input is named as a file in
 * the folder of gtlab's GTAO shaders (techniques/gtao/), so `#include
 * "gtao.inc"` resolves as it does for techniques/gtao/gtao.hlsl. What
 * compiles is a SPIR-V module; what does not, an error of one line.
 * (glslang is Debian's uninstrumented library: the fuzzer sees gtlab's
 * branches, not glslang's.) */
#include <string.h>

#include "fuzz_target.h"
#include "gpu/shader_compiler.h"

enum { SPIRV_MAGIC = 0x07230203u };

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (memchr(data, '\0', size)) /* gpu_read_source refuses such a file */
        return 0;
    char *text = malloc(size + 1);
    FUZZ_REQUIRE(text != NULL);
    memcpy(text, data, size);
    text[size] = '\0';
    const int glsl = strstr(text, "#version") != NULL;
    const char *name =
        glsl ? GTLAB_SOURCE_DIR "/techniques/gtao/fuzz.glsl" : GTLAB_SOURCE_DIR "/techniques/gtao/fuzz.hlsl";
    gpu_spirv spirv;
    gt_error e = {{0}};
    if (gpu_compile_compute(text, name, glsl ? GPU_SOURCE_GLSL : GPU_SOURCE_HLSL, NULL, &spirv, &e) == 0) {
        FUZZ_REQUIRE(spirv.count >= 5 && spirv.words[0] == SPIRV_MAGIC && strcmp(spirv.entry, "main") == 0);
    } else {
        FUZZ_REQUIRE(spirv.words == NULL && spirv.count == 0);
        FUZZ_REQUIRE(e.message[0] != '\0' && strchr(e.message, '\n') == NULL);
    }
    gpu_spirv_free(&spirv);
    free(text);
    return 0;
}
