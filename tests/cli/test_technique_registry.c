/* cli/techniques.c: the registry the verbs and `gtlab all` are built from.
 * Within a verb no two techniques claim one name (the second would never
 * run); stage keys are unique; a stage that reads another's output comes
 * after it and names a stage that declares what it writes; every entry has
 * its help text. */
#include "cli/technique.h"
#include "tests/check.h"

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

static void test_techniques_named(void)
{
    int count = 0;
    for (const technique *const *t = gtlab_techniques; *t; ++t, ++count)
        CHECK((*t)->name && (*t)->name[0]);
    CHECK(count >= 6);
}

int main(void)
{
    test_subcommand_names_unique();
    test_stages_ordered_by_their_inputs();
    test_techniques_named();
    return check_report("cli_technique_registry");
}
