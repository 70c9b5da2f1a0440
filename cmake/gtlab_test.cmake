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
