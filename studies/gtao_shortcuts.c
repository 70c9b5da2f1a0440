/* The shortcut studies of issue 25, items 6-8, on one scene; see
 * gtao_shortcuts.h. */
#include "studies/gtao_shortcuts.h"

int gtao_shortcuts_scene(const gtao_shortcut_scene *s, gtao_shortcuts_result *r, gt_error *e)
{
    return gtao_pattern_scene_study(s, &r->pattern, e);
}

void gtao_shortcuts_finish(gtao_shortcuts_result *r) { gtao_pattern_finish(&r->pattern); }
