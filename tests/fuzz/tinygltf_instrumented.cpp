/* tinygltf 2.7.0 and stb_image 2.27 compiled from Debian's headers for the
 * fuzz build (cmake/gtlab_fuzz.cmake): the same code as Debian's
 * libtinygltf.so and libstb.so, instrumented like the rest of gtlab. */
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>
