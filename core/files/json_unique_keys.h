/* RFC 8259 (section 4) says an object's names SHOULD be unique and leaves
 * what a parser does with a repeated one to the parser: cJSON keeps both and
 * its look-ups find the first, so `{"spp": 4, "spp": 64}` would silently
 * render 4 (issue 41). gtlab's JSON files (project, camera) refuse a
 * repeated name instead, naming it and where it is:
 *
 *   "cam.json: duplicate key 'position' at $ (a key may appear once in an object)"
 *   "gtlab.json: duplicate key 'label' at $.scenes[1]"
 *
 * The walk is iterative (no recursion, tests/audit/no_recursion.sh) over
 * a tree the JSON gate (json_check.h) has already bounded to JSON_MAX_DEPTH. */
#ifndef GTLAB_CORE_FILES_JSON_UNIQUE_KEYS_H
#define GTLAB_CORE_FILES_JSON_UNIQUE_KEYS_H

#include <cjson/cJSON.h>

#include "core/error.h"

/* 0 when no object in the tree repeats a name, or -1 with e as above
 * (what: the file's name). */
int json_check_unique_keys(const cJSON *root, const char *what, gt_error *e);

#endif
