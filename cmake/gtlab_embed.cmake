# gtlab_embed_text(NAME symbol INPUT file OUT var): generates, at build time,
# a C file defining `const char symbol[]` as the text of INPUT byte for byte
# (cmake/embed_text.cmake) and sets var to its path, for a library's SOURCES.
# One source per formula: a .inc written in the common subset of C, HLSL and
# GLSL is compiled as C by its library and embedded, through this, in the
# shaders the library writes.
function(gtlab_embed_text)
  cmake_parse_arguments(ARG "" "NAME;INPUT;OUT" "" ${ARGN})
  if(NOT ARG_NAME OR NOT ARG_INPUT OR NOT ARG_OUT OR ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "gtlab_embed_text(NAME symbol INPUT file OUT var): bad arguments")
  endif()
  set(in ${CMAKE_CURRENT_SOURCE_DIR}/${ARG_INPUT})
  set(out ${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}.c)
  set(script ${PROJECT_SOURCE_DIR}/cmake/embed_text.cmake)
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DIN=${in} -DOUT=${out} -DNAME=${ARG_NAME} -P ${script}
    DEPENDS ${in} ${script}
    COMMENT "Embedding ${ARG_INPUT}")
  set(${ARG_OUT} ${out} PARENT_SCOPE)
endfunction()
