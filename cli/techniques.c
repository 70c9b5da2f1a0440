/* The technique registry: one line per technique, in the order of the
 * report. A technique is defined in cli/technique_<name>.c. */
#include "cli/technique.h"

#define GTLAB_TECHNIQUES(T) \
    T(ao)                   \
    T(gtao)                 \
    T(multibounce)          \
    T(specular_occlusion)   \
    T(sphere_light)         \
    T(dfg)                  \
    T(normals)              \
    T(hdr_precision)        \
    T(color_grading)        \
    T(sg_ndf)               \
    T(anti_aliasing)        \
    T(inside)               \
    T(volumetric)           \
    T(atmosphere)           \
    T(fog)                  \
    T(environment)          \
    T(scale)                \
    T(throughput)           \
    T(shader)

#define DECLARE(name) extern const technique technique_##name;
#define REGISTER(name) &technique_##name,
GTLAB_TECHNIQUES(DECLARE)
const technique *const gtlab_techniques[] = {GTLAB_TECHNIQUES(REGISTER) NULL};

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

int technique_run_verb(technique_verb verb, const char *name, const char *usage, const char *kind, const char *noun,
                       int argc, char **argv)
{
    cli_subcommand table[64];
    const cli_subcommand_verb v = {name, usage, kind, noun, table, technique_subcommands(verb, table, 64)};
    return cli_run_subcommand(&v, argc, argv);
}
