/* Look-ups in a registry of reference quantities (reference_quantity.h).
 * The registry itself is not here: `gtlab`'s is generated from the
 * techniques' folders (cli/render_quantities.h), so the ray tracer names no
 * quantity of a technique (docs/render-quantities.md). */
#include "raytracer/reference_quantity.h"

#include <stdio.h>
#include <string.h>

int reference_quantity_count(const reference_registry *r)
{
    return r->count;
}

reference_quantity reference_quantity_at(const reference_registry *r, int index)
{
    return index >= 0 && index < r->count ? r->quantities[index] : NULL;
}

reference_quantity reference_quantity_find(const reference_registry *r, const char *name)
{
    for (int i = 0; i < r->count; ++i)
        if (strcmp(name, r->quantities[i]->name) == 0)
            return r->quantities[i];
    return NULL;
}

int reference_quantity_parse(const reference_registry *r, const char *name, reference_quantity *q)
{
    reference_quantity found = reference_quantity_find(r, name);
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

void reference_quantity_names(const reference_registry *r, char *text, size_t size)
{
    text[0] = '\0';
    for (int i = 0; i < r->count; ++i)
        reference_append_listed(text, size, i, r->count, " or ", r->quantities[i]->name);
}
