/* The technique registry, in the order of the report: generated from the
 * one list of techniques/CMakeLists.txt (technique_list.inc holds a T(name)
 * per technique). A technique is defined by its folder's command-line face
 * (techniques/<name>/<name>_cli.c). */
#include "cli/technique.h"

#include <string.h>

#define T(name) extern const technique technique_##name;
#include "technique_list.inc"
#undef T
#define T(name) &technique_##name,
const technique *const gtlab_techniques[] = {
#include "technique_list.inc"
    NULL};
#undef T

size_t technique_subcommands(technique_verb verb, cli_subcommand *out, size_t capacity)
{
    size_t n = 0;
    for (const technique *const *t = gtlab_techniques; *t; ++t)
        for (const cli_subcommand *s = (*t)->subcommands[verb]; s && s->name && n < capacity; ++s)
            out[n++] = *s;
    return n;
}

size_t technique_stages(const all_stage **out, size_t capacity)
{
    size_t n = 0;
    for (const technique *const *t = gtlab_techniques; *t; ++t)
        for (const all_stage *s = (*t)->stages; s && s->key && n < capacity; ++s)
            out[n++] = s;
    return n;
}

const char *technique_renamed(const char *former)
{
    for (const technique *const *t = gtlab_techniques; *t; ++t)
        for (const technique_rename *r = (*t)->renamed; r && r->former; ++r)
            if (strcmp(former, r->former) == 0)
                return r->name;
    return NULL;
}

int technique_run_verb(technique_verb verb, const char *name, const char *usage, const char *kind, const char *noun,
                       int argc, char **argv)
{
    cli_subcommand table[64];
    const cli_subcommand_verb v = {name, usage, kind, noun, table, technique_subcommands(verb, table, 64),
                                   technique_renamed};
    return cli_run_subcommand(&v, argc, argv);
}
