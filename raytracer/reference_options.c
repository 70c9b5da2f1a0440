/* The quantities' command-line options, gathered from the registry, and
 * their application to a request; the quantities' settings
 * (reference_quantity.h). */
#include "raytracer/reference_quantity.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raytracer/reference_render.h"

const reference_option *reference_quantity_option(reference_quantity q, const reference_option *option)
{
    for (const reference_option *const *o = q->options; o && *o; ++o)
        if (strcmp((*o)->name, option->name) == 0)
            return *o;
    return NULL;
}

int reference_quantity_lists(reference_quantity q, const reference_option *option)
{
    return reference_quantity_option(q, option) != NULL;
}

/* The first quantity in the registry that lists an option of that name. */
static reference_quantity first_owner(const reference_registry *r, const reference_option *option)
{
    for (int i = 0; i < r->count; ++i)
        if (reference_quantity_lists(r->quantities[i], option))
            return r->quantities[i];
    return NULL;
}

/* Each option counts at its first owner, so a shared one appears once. */
const reference_option *reference_option_at(const reference_registry *r, int index)
{
    for (int i = 0; i < r->count; ++i) {
        reference_quantity q = r->quantities[i];
        for (const reference_option *const *o = q->options; o && *o; ++o)
            if (first_owner(r, *o) == q && index-- == 0)
                return *o;
    }
    return NULL;
}

int reference_option_count(const reference_registry *r)
{
    int count = 0;
    while (reference_option_at(r, count))
        ++count;
    return count;
}

/* The index of the option of that name in reference_option_at's order. */
static int option_index(const reference_registry *r, const reference_option *option)
{
    for (int i = 0; reference_option_at(r, i); ++i)
        if (strcmp(reference_option_at(r, i)->name, option->name) == 0)
            return i;
    return -1;
}

void reference_option_owners(const reference_registry *r, const reference_option *option, const char *last_joint,
                             char *text, size_t size)
{
    int owners = 0, listed = 0;
    for (int i = 0; i < r->count; ++i)
        owners += reference_quantity_lists(r->quantities[i], option);
    text[0] = '\0';
    for (int i = 0; i < r->count; ++i)
        if (reference_quantity_lists(r->quantities[i], option))
            reference_append_listed(text, size, listed++, owners, last_joint, r->quantities[i]->name);
}

/* 1 if an earlier quantity than the i-th lists the very object. */
static int listed_before(const reference_registry *r, int i, const reference_option *object)
{
    for (int k = 0; k < i; ++k)
        if (reference_quantity_option(r->quantities[k], object) == object)
            return 1;
    return 0;
}

void reference_option_help(const reference_registry *r, const reference_option *option, char *text, size_t size)
{
    text[0] = '\0';
    for (int i = 0; i < r->count; ++i) {
        const reference_option *own = reference_quantity_option(r->quantities[i], option);
        if (!own || !own->help || listed_before(r, i, own))
            continue;
        size_t used = strlen(text);
        snprintf(text + used, size - used, "%s%s", used ? "\n" : "", own->help);
    }
}

/* "--x: applies to a and b only" for the first given option q does not list. */
static int refuse_foreign(const reference_registry *r, reference_quantity q, const char *const *values, gt_error *e)
{
    for (int i = 0; reference_option_at(r, i); ++i) {
        const reference_option *o = reference_option_at(r, i);
        if (!values[i] || reference_quantity_lists(q, o))
            continue;
        char subject[128], owners[256];
        snprintf(subject, sizeof subject, "--%s", o->name);
        reference_option_owners(r, o, " and ", owners, sizeof owners);
        return gt_error_set(e, subject, "applies to %s only", owners);
    }
    return 0;
}

/* "<subject>: q needs --a (hint) and --b" when a required option is missing. */
static int require_options(const reference_registry *r, reference_quantity q, const char *const *values,
                           const char *subject, gt_error *e)
{
    int required = 0, missing = 0;
    for (const reference_option *const *o = q->options; o && *o; ++o)
        if ((*o)->required)
            ++required, missing += !values[option_index(r, *o)];
    if (!missing)
        return 0;
    char needs[512] = "";
    int listed = 0;
    for (const reference_option *const *o = q->options; o && *o; ++o) {
        if (!(*o)->required)
            continue;
        char item[256];
        snprintf(item, sizeof item, "--%s%s%s%s", (*o)->name, (*o)->hint ? " (" : "", (*o)->hint ? (*o)->hint : "",
                 (*o)->hint ? ")" : "");
        reference_append_listed(needs, sizeof needs, listed++, required, " and ", item);
    }
    return gt_error_set(e, subject, "%s needs %s", q->name, needs);
}

int reference_options_apply(const reference_registry *r, reference_request *rq, const char *const *values,
                            const char *subject, gt_error *e)
{
    reference_quantity q = rq->quantity;
    if (refuse_foreign(r, q, values, e) != 0 || require_options(r, q, values, subject, e) != 0)
        return -1;
    for (const reference_option *const *o = q->options; o && *o; ++o) {
        const char *value = values[option_index(r, *o)];
        if (value && (*o)->parse(rq, (*o)->value ? value : NULL, e) != 0)
            return -1;
    }
    return 0;
}

reference_settings *reference_settings_new(reference_quantity q)
{
    reference_settings *s = q->settings_size ? calloc(1, q->settings_size) : NULL;
    if (s)
        s->quantity = q;
    return s;
}

reference_settings *reference_settings_of(const reference_request *rq, reference_quantity q)
{
    return rq->settings && rq->settings->quantity == q ? rq->settings : NULL;
}
