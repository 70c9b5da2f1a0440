/* scene_list_section without a project: one sentence names the built-in
 * set the scene-driven sections run on, the study scenes and then the
 * procedural family's members exactly as project/scene_list.h lists them,
 * and summary.json's "study_scenes" holds the same names in the same order;
 * with no family member asked for, the sentence names none. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "project/scene_list.h"
#include "report/scene_list_section.h"
#include "scene/builtin_scenes.h"
#include "tests/section_test.h"

static char *report_markdown(section_test *t)
{
    gt_error e;
    char path[4096];
    CHECK_MSG(report_write(&t->doc, t->dir, &e) == 0, "%s", e.message);
    snprintf(path, sizeof path, "%s/report.md", t->dir);
    FILE *f = fopen(path, "rb");
    static char text[1 << 16];
    size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
    text[n] = '\0';
    if (f)
        fclose(f);
    return text;
}

static void check_set(int study_scenes, const char *name)
{
    section_test t;
    section_test_begin(&t, name, NULL);
    t.ctx.study.study_scenes = study_scenes;
    scene_list_section(&t.ctx, NULL, NULL);
    const int count = study_scene_count(&t.ctx.study), builtins = builtin_study_scene_count();
    const cJSON *names = cJSON_GetObjectItemCaseSensitive(t.ctx.summary, "study_scenes");
    CHECK(cJSON_GetArraySize(names) == count);
    for (int i = 0; i < count && i < cJSON_GetArraySize(names); ++i)
        CHECK(strcmp(cJSON_GetArrayItem(names, i)->valuestring, study_scene_at(&t.ctx.study, i)->label) == 0);
    const char *md = report_markdown(&t);
    char want[256];
    snprintf(want, sizeof want, "run on %d built-in scenes: the %d study scenes (%s, ", count, builtins,
             study_scene_at(NULL, 0)->label);
    CHECK_MSG(strstr(md, want) != NULL, "no '%s' in\n%s", want, md);
    if (count > builtins) {
        snprintf(want, sizeof want, "%d member%s of the procedural family (%s", count - builtins,
                 count - builtins == 1 ? "" : "s", study_scene_at(&t.ctx.study, builtins)->label);
        CHECK_MSG(strstr(md, want) != NULL, "no '%s' in\n%s", want, md);
    } else
        CHECK(strstr(md, "procedural") == NULL);
    section_test_end(&t);
}

int main(void)
{
    check_set(0, "builtins_only");
    check_set(builtin_study_scene_count() + 2, "with_family");
    return check_report("report_scene_list_section");
}
