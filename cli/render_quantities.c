/* The registry of render quantities (render_quantities.h), from the list
 * techniques/CMakeLists.txt generates: one Q(descriptor) per quantity. */
#include "cli/render_quantities.h"

#define Q(descriptor) extern const reference_quantity_descriptor descriptor;
#include "reference_quantity_list.inc"
#undef Q

#define Q(descriptor) &descriptor,
static const reference_quantity quantities[] = {
#include "reference_quantity_list.inc"
};
#undef Q

static const reference_registry registry = {quantities, (int)(sizeof quantities / sizeof quantities[0])};

const reference_registry *render_quantities(void)
{
    return &registry;
}
