/* `gtlab bench shader`'s study (shader/shader_bench.h) on a small image: a
 * frame's wall time holds its dispatch (the fence wait is inside the frame's
 * loop), so 0 <= overhead < 1, and the set-up spread over the frames only
 * adds to it; a missing shader is one line naming it. */
#include <stdio.h>
#include <string.h>

#include "shader/shader_bench.h"
#include "tests/check.h"

int main(void)
{
    shader_bench_request r = {GTLAB_SOURCE_DIR "/shaders/template_screen_space.hlsl", "builtin:boxes", NULL, 64, 48, 3, 2};
    shader_bench_result b;
    gt_error e = {{0}};
    int rc = shader_bench_run(&r, &b, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    if (rc == 0) {
        shader_bench_print(stdout, &r, &b);
        CHECK(b.time.dispatch_seconds > 0.0 && b.time.dispatch_seconds <= b.time.frame_seconds);
        CHECK(b.overhead >= 0.0 && b.overhead < 1.0 && b.overhead_amortised >= b.overhead);
        CHECK(b.time.setup_seconds > 0.0 && b.compile_seconds > 0.0 && b.frames == 3 && b.width == 64);
    }
    r.shader = "no_such_shader.glsl";
    CHECK(shader_bench_run(&r, &b, &e) != 0);
    CHECK_MSG(strstr(e.message, "no_such_shader.glsl: cannot open: No such file or directory") != NULL, "%s", e.message);
    return check_report("test_gpu_shader_bench");
}
