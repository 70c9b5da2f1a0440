/* The registry of reference quantities: one line per quantity, in the order
 * of `gtlab render --help` and of the names in its messages. Adding a
 * quantity: define its descriptor in raytracer/<quantity>_quantity.c and add
 * one X(...) line below (docs/render-quantities.md). */
#include "raytracer/reference_quantity.h"

#include <stdio.h>
#include <string.h>

#define REFERENCE_QUANTITIES(X)                                                                                    \
    X(reference_quantity_gbuffer)                                                                                  \
    X(reference_quantity_ao)                                                                                       \
    X(reference_quantity_multibounce)                                                                              \
    X(reference_quantity_heightfield_ao)                                                                           \
    X(reference_quantity_heightfield_multibounce)                                                                  \
    X(reference_quantity_specular_occlusion)                                                                       \
    X(reference_quantity_sphere_light)                                                                             \
    X(reference_quantity_fog)                                                                                      \
    X(reference_quantity_volumetric_light)                                                                        \
    X(reference_quantity_env_diffuse)                                                                              \
    X(reference_quantity_env_specular)

#define DECLARE(descriptor) extern const reference_quantity_descriptor descriptor;
REFERENCE_QUANTITIES(DECLARE)
#define ENTRY(descriptor) &descriptor,
static const reference_quantity registry[] = {REFERENCE_QUANTITIES(ENTRY)};
enum { QUANTITY_COUNT = sizeof registry / sizeof registry[0] };

int reference_quantity_count(void)
{
    return QUANTITY_COUNT;
}

reference_quantity reference_quantity_at(int index)
{
    return index >= 0 && index < QUANTITY_COUNT ? registry[index] : NULL;
}

reference_quantity reference_quantity_find(const char *name)
{
    for (int i = 0; i < QUANTITY_COUNT; ++i)
        if (strcmp(name, registry[i]->name) == 0)
            return registry[i];
    return NULL;
}

int reference_quantity_parse(const char *name, reference_quantity *q)
{
    reference_quantity found = reference_quantity_find(name);
    if (!found)
        return -1;
    *q = found;
    return 0;
}

const char *reference_quantity_name(reference_quantity q)
{
    return q ? q->name : "unknown";
}

void reference_append_listed(char *text, size_t size, int i, int n, const char *last_joint, const char *item)
{
    size_t used = strlen(text);
    const char *joint = i == 0 ? "" : i == n - 1 ? last_joint : ", ";
    snprintf(text + used, size - used, "%s%s", joint, item);
}

void reference_quantity_names(char *text, size_t size)
{
    text[0] = '\0';
    for (int i = 0; i < QUANTITY_COUNT; ++i)
        reference_append_listed(text, size, i, QUANTITY_COUNT, " or ", registry[i]->name);
}
