/* The scenes of GTAO's runs in the talk's setting (gtao_shortcuts.h)
 * in words, for the subsections' paragraphs and claims rows. */
#ifndef GTLAB_GTAO_GTAO_TALK_TEXT_H
#define GTLAB_GTAO_GTAO_TALK_TEXT_H

#include <stddef.h>

#include "gtao/gtao_shortcuts.h" /* gtao_talk_result */

/* "boxes and cornell": the talk-setting scenes in words ("no scene" if none). */
void gtao_talk_scenes_text(const gtao_talk_result *t, char *text, size_t size);
/* The same of any list of names. */
void gtao_scene_names_text(const char (*names)[64], int count, char *text, size_t size);

#endif
