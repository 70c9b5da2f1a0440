# The layering the build enforces (docs/design.md, "Dependencies point one
# way"). There is no include path to the repository root: a target sees the
# headers of its own folder and of the libraries it links, nothing else.
#
# Includes keep their "folder/file.h" form. For each folder F, configure
# creates ${CMAKE_BINARY_DIR}/layers/F/ holding a single symbolic link
# F -> ${PROJECT_SOURCE_DIR}/F; that directory is F's include path, so
# "F/x.h" resolves and "G/y.h" for any other folder G does not, unless G's
# library is linked (its include path then propagates through
# target_link_libraries as a PUBLIC usage requirement).

# Sets out_var to the include directory that exposes the folder (and only it).
function(gtlab_layer_dir folder out_var)
  set(dir ${CMAKE_BINARY_DIR}/layers/${folder})
  if(NOT IS_SYMLINK ${dir}/${folder})
    file(MAKE_DIRECTORY ${dir})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${dir}/${folder} SYMBOLIC)
  endif()
  set(${out_var} ${dir} PARENT_SCOPE)
endfunction()

# gtlab_library(NAME folder SOURCES file... [PUBLIC lib...] [PRIVATE lib...])
# The static library gtlab_<folder> from the folder's sources, seeing its own
# headers. PUBLIC: libraries its public headers include (their headers become
# visible to whoever links it); PRIVATE: libraries only its sources use.
function(gtlab_library)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  if(NOT ARG_NAME OR NOT ARG_SOURCES OR ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "gtlab_library(NAME folder SOURCES ... [PUBLIC ...] [PRIVATE ...]): bad arguments")
  endif()
  set(target gtlab_${ARG_NAME})
  gtlab_layer_dir(${ARG_NAME} layer)
  add_library(${target} STATIC ${ARG_SOURCES})
  target_include_directories(${target} PUBLIC ${layer})
  target_link_libraries(${target} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
endfunction()
