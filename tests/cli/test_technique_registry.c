/* cli/techniques.c: the registry the verbs and `gtlab all` are built from.
 * Within a verb no two techniques claim one name (the second would never
 * run); stage keys are unique; a stage that reads another's output comes
 * after it and names a stage that declares what it writes; every entry has
 * its help text; a technique is named after its folder (techniques/height_fog
 * is "height-fog"), and a former name names no current stage or subcommand
 * and leads to one. */
#include "cli/technique.h"
#include "tests/check.h"

#include <stdio.h>
#include <string.h>

static void test_subcommand_names_unique(void)
{
    for (int v = 0; v < VERB_KIND_COUNT; ++v) {
        cli_subcommand s[64];
        size_t n = technique_subcommands((technique_verb)v, s, 64);
        CHECK(n < 64);
        for (size_t i = 0; i < n; ++i) {
            CHECK_MSG(s[i].run && s[i].summary && s[i].summary[0], "%s has no entry point or help", s[i].name);
            for (size_t j = 0; j < i; ++j)
                CHECK_MSG(strcmp(s[i].name, s[j].name) != 0, "verb %d: %s registered twice", v, s[i].name);
        }
    }
}

static void test_stages_ordered_by_their_inputs(void)
{
    const all_stage *st[64];
    size_t n = technique_stages(st, 64);
    CHECK(n >= 6 && n < 64);
    for (size_t i = 0; i < n; ++i) {
        CHECK_MSG(st[i]->run && st[i]->title, "stage %s incomplete", st[i]->key);
        int found = !st[i]->needs;
        for (size_t j = 0; j < i; ++j) {
            CHECK_MSG(strcmp(st[i]->key, st[j]->key) != 0, "stage %s registered twice", st[i]->key);
            if (st[i]->needs && strcmp(st[i]->needs, st[j]->key) == 0)
                found = st[j]->writes != NULL;
        }
        CHECK_MSG(found, "stage %s needs %s, which is not an earlier stage that writes a folder", st[i]->key,
                  st[i]->needs);
    }
}

/* The registry's own list of folders (technique_list.inc), in its order. */
#define T(name) #name,
static const char *const folders[] = {
#include "technique_list.inc"
    NULL};
#undef T

static void test_techniques_named_after_their_folders(void)
{
    int count = 0;
    for (const technique *const *t = gtlab_techniques; *t; ++t, ++count) {
        CHECK(folders[count] != NULL);
        char kebab[64];
        snprintf(kebab, sizeof kebab, "%s", folders[count]);
        for (char *c = kebab; *c; ++c)
            *c = *c == '_' ? '-' : *c;
        CHECK_MSG((*t)->name && strcmp((*t)->name, kebab) == 0, "techniques/%s is named '%s', not '%s'", folders[count],
                  (*t)->name ? (*t)->name : "(none)", kebab);
    }
    CHECK(count >= 6);
}

/* Whether `name` is a stage key or a subcommand of any verb today. */
static int name_in_use(const char *name)
{
    const all_stage *st[64];
    size_t n = technique_stages(st, 64);
    for (size_t i = 0; i < n; ++i)
        if (strcmp(st[i]->key, name) == 0)
            return 1;
    for (int v = 0; v < VERB_KIND_COUNT; ++v) {
        cli_subcommand s[64];
        size_t k = technique_subcommands((technique_verb)v, s, 64);
        for (size_t i = 0; i < k; ++i)
            if (strcmp(s[i].name, name) == 0)
                return 1;
    }
    return 0;
}

static void test_former_names_lead_somewhere(void)
{
    int renames = 0;
    for (const technique *const *t = gtlab_techniques; *t; ++t)
        for (const technique_rename *r = (*t)->renamed; r && r->former; ++r, ++renames) {
            CHECK_MSG(!name_in_use(r->former), "%s: former name '%s' is still in use", (*t)->name, r->former);
            CHECK_MSG(name_in_use(r->name), "%s: '%s' is now '%s', which nothing is named", (*t)->name, r->former,
                      r->name);
            CHECK(strcmp(technique_renamed(r->former), r->name) == 0);
        }
    CHECK(renames >= 4);
    CHECK(technique_renamed("anti-aliasing") == NULL && technique_renamed("no-such-name") == NULL);
}

int main(void)
{
    test_subcommand_names_unique();
    test_stages_ordered_by_their_inputs();
    test_techniques_named_after_their_folders();
    test_former_names_lead_somewhere();
    return check_report("cli_technique_registry");
}
