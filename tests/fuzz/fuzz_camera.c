/* Fuzz target "camera": camera JSON (scene/camera.h), as --camera files and
 * the gtlab.camera header attribute give it. A camera that parses is valid,
 * and the JSON gtlab writes for it parses back. */
#include <stdlib.h>
#include <string.h>

#include "fuzz_target.h"
#include "scene/camera.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    camera cam;
    gt_error e;
    if (camera_parse_json_bytes((const char *)data, size, "fuzz.json", &cam, &e) != 0)
        return 0;
    FUZZ_REQUIRE(camera_validate(&cam, "fuzz.json", &e) == 0);
    char *text = camera_to_json(&cam);
    FUZZ_REQUIRE(text != NULL);
    camera again;
    FUZZ_REQUIRE(camera_parse_json(text, "written", &again, &e) == 0);
    free(text);
    return 0;
}
