/* The talk-setting runs' scenes in words; see gtao_talk_text.h. */
#include "gtao/gtao_talk_text.h"

#include <stdio.h>

void gtao_scene_names_text(const char (*names)[64], int count, char *text, size_t size)
{
    size_t used = (size_t)snprintf(text, size, "%s", count == 0 ? "no scene" : "");
    for (int i = 0; i < count && used < size; ++i)
        used += (size_t)snprintf(text + used, size - used, "%s%s", i == 0 ? "" : i + 1 == count ? " and " : ", ",
                                 names[i]);
}

void gtao_talk_scenes_text(const gtao_talk_result *t, char *text, size_t size)
{
    gtao_scene_names_text((const char (*)[64])t->scenes, t->scene_count, text, size);
}
