# Each test is a plain executable (returns non-zero on failure) or a CLI
# scenario; ctest runs them all.
#
# gtlab_test(NAME name SOURCES file... LIBS lib...): a test linked to the
# libraries it tests and nothing more, so it sees only their headers (and
# tests/, as "tests/check.h"), as the libraries themselves do
# (cmake/gtlab_layers.cmake).
gtlab_layer_dir(tests tests_layer)
function(gtlab_test)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;LIBS" ${ARGN})
  if(NOT ARG_NAME OR NOT ARG_SOURCES OR NOT ARG_LIBS OR ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "gtlab_test(NAME name SOURCES ... LIBS ...): bad arguments")
  endif()
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_include_directories(${ARG_NAME} PRIVATE ${tests_layer})
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_LIBS})
  add_test(NAME ${ARG_NAME} COMMAND ${ARG_NAME})
  # A folder of its own beside the executables: a test's files never collide
  # with a test executable's name.
  file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/test-files)
  set_tests_properties(${ARG_NAME} PROPERTIES ENVIRONMENT "GTLAB_TEST_TMP=${CMAKE_CURRENT_BINARY_DIR}/test-files")
endfunction()

# Under AddressSanitizer the Vulkan loader unloads the driver (lavapipe) at
# vkDestroyInstance, before LeakSanitizer looks: what the driver still holds
# then shows as leaks from an "<unknown module>" no suppression can name.
# Preloading the driver keeps it resident (the loader's dlclose leaves it),
# so its memory stays reachable and gtlab's own allocations stay checked.
# libasan must come first in the preload list. GTLAB_VULKAN_PRELOAD holds
# it (empty without ASan or lavapipe): a CLI test that runs gtlab on Vulkan
# (tests/cli) gives it to gtlab alone, as bash and python3 are not built
# with ASan; gtlab_vulkan_preload(test...) preloads it for test executables.
set(GTLAB_VULKAN_PRELOAD "")
if(GTLAB_SANITIZE)
  execute_process(COMMAND ${CMAKE_C_COMPILER} -print-file-name=libasan.so OUTPUT_VARIABLE gtlab_libasan
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  find_library(gtlab_vulkan_driver NAMES vulkan_lvp)
  if(gtlab_vulkan_driver AND EXISTS "${gtlab_libasan}")
    set(GTLAB_VULKAN_PRELOAD "${gtlab_libasan} ${gtlab_vulkan_driver}")
  endif()
endif()

function(gtlab_vulkan_preload)
  if(GTLAB_VULKAN_PRELOAD)
    set_property(TEST ${ARGN} APPEND PROPERTY ENVIRONMENT "LD_PRELOAD=${GTLAB_VULKAN_PRELOAD}")
  endif()
endfunction()

# gtlab_gpu_test(NAME name SOURCES file... LIBS lib...): a gtlab_test that
# needs a Vulkan device with a compute queue (lavapipe is enough; without
# one it fails, it never skips), with the driver preloaded under ASan.
function(gtlab_gpu_test)
  gtlab_test(${ARGN})
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;LIBS" ${ARGN})
  gtlab_vulkan_preload(${ARG_NAME})
endfunction()
