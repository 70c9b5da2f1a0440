/* Repeated object names refused; see json_unique_keys.h. */
#include "core/files/json_unique_keys.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/json_check.h"

static int compare_names(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* A name that two members of object o share (NULL: none), in O(n log n)
 * so a hostile object of many keys costs no more than reading it; sets
 * *out_of_memory when the names could not be gathered. */
static const char *repeated_name(const cJSON *o, int *out_of_memory)
{
    size_t n = 0;
    for (const cJSON *c = o->child; c; c = c->next)
        n += c->string != NULL;
    if (n < 2)
        return NULL;
    const char **names = malloc(n * sizeof *names);
    if (!names)
        return *out_of_memory = 1, NULL;
    size_t k = 0;
    for (const cJSON *c = o->child; c; c = c->next)
        if (c->string)
            names[k++] = c->string;
    qsort(names, n, sizeof *names, compare_names);
    const char *repeated = NULL;
    for (size_t i = 1; i < n && !repeated; ++i)
        if (strcmp(names[i - 1], names[i]) == 0)
            repeated = names[i];
    free(names);
    return repeated;
}

/* "$.scenes[1].cameras" for the containers path[0..depth) on the walk's
 * stack (each node's key or index within its parent). */
static void describe_path(const cJSON *const *path, int depth, char *out, size_t size)
{
    size_t k = (size_t)snprintf(out, size, "$");
    for (int d = 1; d < depth && k < size; ++d) {
        const cJSON *node = path[d];
        if (cJSON_IsArray(path[d - 1])) {
            int index = 0;
            for (const cJSON *c = path[d - 1]->child; c && c != node; c = c->next)
                ++index;
            k += (size_t)snprintf(out + k, size - k, "[%d]", index);
        } else {
            k += (size_t)snprintf(out + k, size - k, ".%s", node->string ? node->string : "?");
        }
    }
}

int json_check_unique_keys(const cJSON *root, const char *what, gt_error *e)
{
    const cJSON *path[JSON_MAX_DEPTH + 2];
    int depth = 0;
    const cJSON *node = root;
    while (node) {
        if (depth > JSON_MAX_DEPTH)
            return gt_error_set(e, what, "nested deeper than %d", JSON_MAX_DEPTH);
        path[depth++] = node;
        int out_of_memory = 0;
        const char *repeated = cJSON_IsObject(node) ? repeated_name(node, &out_of_memory) : NULL;
        if (out_of_memory)
            return gt_error_set(e, what, "out of memory checking its keys");
        if (repeated) {
            char where[512];
            describe_path(path, depth, where, sizeof where);
            return gt_error_set(e, what, "duplicate key '%.200s' at %s (a key may appear once in an object)",
                                repeated, where);
        }
        if ((cJSON_IsObject(node) || cJSON_IsArray(node)) && node->child) {
            node = node->child; /* down */
            continue;
        }
        /* Up until a container with a next sibling, then across. */
        for (--depth; depth > 0 && !path[depth]->next; --depth)
            ;
        node = depth > 0 ? path[depth]->next : NULL;
    }
    return 0;
}
