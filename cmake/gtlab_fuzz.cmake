# Fuzzing (issue 21; docs/decisions.md, "Fuzzing"). With -DGTLAB_FUZZ=ON and
# clang as the compiler, in a build folder of its own:
#   CC=clang CXX=clang++ cmake -S . -B build-fuzz -DGTLAB_FUZZ=ON
#   cmake --build build-fuzz --target gtlab_fuzz_targets -j2
# every library is compiled with libFuzzer's coverage instrumentation and
# AddressSanitizer + UndefinedBehaviorSanitizer, and tests/fuzz builds one
# libFuzzer executable per input parser. tinygltf and stb_image, which a
# normal build takes from Debian's shared libraries, are compiled here from
# Debian's headers (the sources those libraries are built from), so that the
# fuzzer sees their branches and the sanitizers their memory accesses.
#
# GTLAB_TINYGLTF: what scene/ links for tinygltf (and stb_image, whose
# stbi_info_from_memory the glTF reader calls).
option(GTLAB_FUZZ "Build the libFuzzer targets of tests/fuzz (clang only)" OFF)
if(GTLAB_FUZZ)
  if(NOT CMAKE_C_COMPILER_ID STREQUAL "Clang" OR NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "GTLAB_FUZZ needs clang: CC=clang CXX=clang++ cmake -S . -B build-fuzz -DGTLAB_FUZZ=ON")
  endif()
  if(GTLAB_SANITIZE)
    message(FATAL_ERROR "GTLAB_FUZZ already builds with the sanitizers; leave GTLAB_SANITIZE off")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined)
  # clang 14 emits no resolver for a target_clones function that its own
  # file does not call (the AVX2 batch loops of core/): one plain version
  # each here; the attribute becomes the harmless `unused`.
  add_compile_options("$<$<COMPILE_LANGUAGE:C>:-Dtarget_clones(...)=unused>")
  add_link_options(-fsanitize=address,undefined)
  # libFuzzer's convention: limits that only cost time when fuzzing are
  # lowered (core/files/exr_io.c, scene/gltf/gltf_reader.cpp, scene/gltf/gltf_accessors.cpp).
  add_compile_definitions(FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION)
  add_library(gtlab_tinygltf_instrumented STATIC ${PROJECT_SOURCE_DIR}/tests/fuzz/tinygltf_instrumented.cpp)
  target_include_directories(gtlab_tinygltf_instrumented SYSTEM PUBLIC /usr/include/stb)
  # Debian's header, compiled as Debian compiles it: warnings are upstream's.
  target_compile_options(gtlab_tinygltf_instrumented PRIVATE -w)
  set(GTLAB_TINYGLTF gtlab_tinygltf_instrumented)
else()
  set(GTLAB_TINYGLTF TinyGLTF::TinyGLTF stb)
endif()
