# One technique, one folder (issue 43; docs/design.md, "Techniques"): a
# technique's folder techniques/<name>/ holds its reference, real-time code,
# LUTs, fits, study, report section, command-line face, tests and README.md.
# Its CMakeLists.txt is one gtlab_technique() call naming which file belongs
# to which part; each part is a library the build layers exactly as the
# shared folders are (cmake/gtlab_layers.cmake):
#
#   part        links (and so sees)
#   LUTS        luts/ core/                       tables, their writers
#   REALTIME    its LUTS, realtime/ luts/ core/   what a shader runs
#   REFERENCE   raytracer/ scene/ core/           the ground truth
#   FIT         its REALTIME, fitters/            Ceres fits of the real-time code
#   STUDY       its parts below, project/ (and all below it)
#   SECTION     its STUDY, report/
#   CLI         compiled into cli/ (the verbs and `gtlab all` from the registry)
#
# QUANTITIES d...: the render quantities its REFERENCE part defines, by their
# descriptors (`QUANTITIES reference_quantity_fog`): `gtlab render`'s registry
# is generated from them (techniques/CMakeLists.txt, cli/render_quantities.h),
# so a technique adds a quantity in its folder alone.
#
# USES t...: the technique builds on technique t: each of its parts links t's
# part of the same name, where t has one (a declared, one-way dependency:
# GTSO's study uses GTAO's AO). Headers are included as "<name>/file.h"; a
# part's include path holds links to its own headers only, so a part cannot
# include a part above it (tests/layering probes it for every technique).
# The include name is the file's name whatever subfolder holds it, so moving a
# file into study/ changes no #include.
#
# Every file in the folder belongs to exactly one part (CMakeLists.txt and
# README.md aside; tests/ holds its tests): a file in none is a configure
# error, so a new file cannot silently escape the layering.

include(${CMAKE_CURRENT_LIST_DIR}/gtlab_quality.cmake) # gtlab_quality_header()
set(GTLAB_TECHNIQUE_PARTS LUTS REALTIME REFERENCE FIT STUDY SECTION)
# The shared library each part stands on.
set(gtlab_part_base_LUTS gtlab_luts)
set(gtlab_part_base_REALTIME gtlab_realtime)
set(gtlab_part_base_REFERENCE gtlab_raytracer)
set(gtlab_part_base_FIT gtlab_fitters)
set(gtlab_part_base_STUDY gtlab_project)
set(gtlab_part_base_SECTION gtlab_report)
# The technique's own parts each part links (those that exist).
set(gtlab_part_below_LUTS "")
set(gtlab_part_below_REALTIME LUTS)
set(gtlab_part_below_REFERENCE "")
set(gtlab_part_below_FIT REALTIME LUTS)
set(gtlab_part_below_STUDY FIT REFERENCE REALTIME LUTS)
set(gtlab_part_below_SECTION STUDY FIT REFERENCE REALTIME LUTS)

# The target of technique `name`'s part `part` (whether or not it exists).
function(gtlab_technique_target name part out_var)
  string(TOLOWER ${part} lower)
  set(${out_var} gtlab_${name}_${lower} PARENT_SCOPE)
endfunction()

# Configure error unless every file of the folder is named by one part. A
# part's files may sit in a subfolder named after it (study/, section/: a
# folder that would otherwise hold more than 40 files keeps its study and
# section there), named by their path in the folder ("study/gtao_params.c").
function(gtlab_technique_check_files name listed)
  file(RELATIVE_PATH folder ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR}/)
  file(GLOB_RECURSE present RELATIVE ${CMAKE_CURRENT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR}/*)
  foreach(file IN LISTS present)
    if(file STREQUAL "CMakeLists.txt" OR file MATCHES "(^|/)README\\.md$" OR file MATCHES "^tests/")
      continue()
    endif()
    list(FIND listed ${file} at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${folder}${file} belongs to no part of gtlab_technique(NAME ${name})")
    endif()
    list(REMOVE_AT listed ${at})
    list(FIND listed ${file} again)
    if(NOT again EQUAL -1)
      message(FATAL_ERROR "${folder}${file} is named by two parts of gtlab_technique(NAME ${name})")
    endif()
  endforeach()
  foreach(file IN LISTS listed)
    if(NOT EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${file})
      message(FATAL_ERROR "${folder}: gtlab_technique names ${file}, which does not exist")
    endif()
  endforeach()
endfunction()

# Configure error unless the folder's file names are unique whatever subfolder
# holds them: a header is included as "<name>/<file name>" from any subfolder.
function(gtlab_technique_check_names name listed)
  set(seen)
  foreach(file IN LISTS listed)
    get_filename_component(base ${file} NAME)
    if(base IN_LIST seen)
      message(FATAL_ERROR "techniques/${name}: two files are named ${base} (a header is included as ${name}/${base})")
    endif()
    list(APPEND seen ${base})
  endforeach()
endfunction()

# The include directory of one part: <dir>/<name>/ holds a link to each of the
# part's headers (by file name, whatever subfolder holds it), and nothing else
# of the folder.
function(gtlab_technique_part_layer name part files out_var)
  set(dir ${CMAKE_BINARY_DIR}/layers/techniques/${name}/${part})
  file(MAKE_DIRECTORY ${dir}/${name})
  foreach(file IN LISTS files)
    get_filename_component(base ${file} NAME)
    set(link ${dir}/${name}/${base})
    set(target ${CMAKE_CURRENT_SOURCE_DIR}/${file})
    if(file MATCHES "\\.(c|cpp)$")
      continue()
    endif()
    if(IS_SYMLINK ${link})
      file(READ_SYMLINK ${link} linked)
      if(linked STREQUAL target)
        continue()
      endif()
      file(REMOVE ${link}) # the file moved within the folder
    endif()
    file(CREATE_LINK ${target} ${link} SYMBOLIC)
  endforeach()
  # A header that left the part (moved to another part, or deleted) leaves no
  # link behind, or the part would still see it.
  file(GLOB linked_names RELATIVE ${dir}/${name} ${dir}/${name}/*)
  foreach(base IN LISTS linked_names)
    set(named FALSE)
    foreach(file IN LISTS files)
      get_filename_component(file_base ${file} NAME)
      if(file_base STREQUAL base)
        set(named TRUE)
      endif()
    endforeach()
    if(NOT named)
      file(REMOVE ${dir}/${name}/${base})
    endif()
  endforeach()
  set(${out_var} ${dir} PARENT_SCOPE)
endfunction()

# The libraries part `part` of technique `name` links: its base, its own
# parts below it and, for each technique it uses, that technique's part.
function(gtlab_technique_part_links name part uses out_var)
  set(links ${gtlab_part_base_${part}})
  foreach(below IN LISTS gtlab_part_below_${part})
    gtlab_technique_target(${name} ${below} target)
    if(TARGET ${target})
      list(APPEND links ${target})
    endif()
  endforeach()
  foreach(used IN LISTS uses)
    gtlab_technique_target(${used} ${part} target)
    if(TARGET ${target})
      list(APPEND links ${target})
    endif()
  endforeach()
  set(${out_var} ${links} PARENT_SCOPE)
endfunction()

# One part as a library: static when it has sources, else an interface
# library carrying its headers' include path and links.
function(gtlab_technique_part name part files uses)
  gtlab_technique_target(${name} ${part} target)
  gtlab_technique_part_layer(${name} ${part} "${files}" layer)
  gtlab_technique_part_links(${name} ${part} "${uses}" links)
  set(sources ${files})
  list(FILTER sources INCLUDE REGEX "\\.(c|cpp)$")
  if(sources)
    add_library(${target} STATIC ${sources})
    target_include_directories(${target} PUBLIC ${layer})
    target_link_libraries(${target} PUBLIC ${links})
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE ${layer})
    target_link_libraries(${target} INTERFACE ${links})
  endif()
  # For tests/layering: the part and one of its headers, which every part
  # above it must see and every part below it must not.
  set(headers ${files})
  list(FILTER headers INCLUDE REGEX "\\.h$")
  if(headers)
    list(GET headers 0 header)
    get_filename_component(header ${header} NAME) # included by its name, whatever subfolder holds it
    set_property(GLOBAL APPEND PROPERTY GTLAB_TECHNIQUE_PARTS_BUILT "${name}:${part}:${header}")
  endif()
endfunction()

# gtlab_technique(NAME name [USES technique...] [QUANTITIES descriptor...]
#                 [LUTS file...] [REALTIME file...]
#                 [REFERENCE file...] [FIT file...] [STUDY file...]
#                 [SECTION file...] [CLI file...] [LINKS lib...])
# LINKS: further libraries the technique's sources need (e.g. a Debian
# library only it uses), linked privately by its topmost part.
function(gtlab_technique)
  cmake_parse_arguments(ARG "" "NAME" "USES;QUANTITIES;LUTS;REALTIME;REFERENCE;FIT;STUDY;SECTION;CLI;LINKS" ${ARGN})
  if(NOT ARG_NAME OR ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "gtlab_technique(NAME name [USES ...] [QUANTITIES ...] [LUTS ...] ... [CLI ...]): bad arguments")
  endif()
  if(ARG_QUANTITIES AND NOT ARG_REFERENCE)
    message(FATAL_ERROR "gtlab_technique(NAME ${ARG_NAME}): QUANTITIES without a REFERENCE part to define them")
  endif()
  set_property(GLOBAL PROPERTY GTLAB_TECHNIQUE_QUANTITIES_${ARG_NAME} ${ARG_QUANTITIES})
  set(listed)
  foreach(part IN LISTS GTLAB_TECHNIQUE_PARTS ITEMS CLI)
    list(APPEND listed ${ARG_${part}})
  endforeach()
  gtlab_technique_check_files(${ARG_NAME} "${listed}")
  gtlab_technique_check_names(${ARG_NAME} "${listed}")
  get_property(configured GLOBAL PROPERTY GTLAB_TECHNIQUES_CONFIGURED)
  foreach(used IN LISTS ARG_USES)
    if(NOT used IN_LIST configured)
      message(FATAL_ERROR "gtlab_technique(NAME ${ARG_NAME}): USES ${used}, which is not built before it "
                          "(list ${used} earlier in techniques/CMakeLists.txt)")
    endif()
  endforeach()
  set_property(GLOBAL APPEND PROPERTY GTLAB_TECHNIQUES_CONFIGURED ${ARG_NAME})
  set(top)
  foreach(part IN LISTS GTLAB_TECHNIQUE_PARTS)
    if(ARG_${part})
      gtlab_technique_part(${ARG_NAME} ${part} "${ARG_${part}}" "${ARG_USES}")
      gtlab_technique_target(${ARG_NAME} ${part} top)
    endif()
  endforeach()
  if(ARG_LINKS AND top)
    target_link_libraries(${top} PRIVATE ${ARG_LINKS})
  endif()
  set(study)
  if(ARG_STUDY)
    gtlab_technique_target(${ARG_NAME} STUDY study)
  endif()
  gtlab_quality_header(${ARG_NAME} "${study}")
  list(TRANSFORM ARG_CLI PREPEND ${CMAKE_CURRENT_SOURCE_DIR}/)
  set_property(GLOBAL APPEND PROPERTY GTLAB_TECHNIQUE_CLI_SOURCES ${ARG_CLI})
  if(top)
    set_property(GLOBAL APPEND PROPERTY GTLAB_TECHNIQUE_LIBRARIES ${top})
  endif()
endfunction()

# The render registry's quantities in order (techniques/CMakeLists.txt,
# docs/render-quantities.md): those of `order` first, then the rest of
# `shared` and of the techniques' QUANTITIES (in the order of `techniques`).
# A quantity declared twice (by two techniques, or by one and `shared`) or
# one `order` names that nobody declares is a configure error.
function(gtlab_render_quantity_list out_var techniques shared order)
  set(declared ${shared})
  foreach(name IN LISTS techniques)
    get_property(quantities GLOBAL PROPERTY GTLAB_TECHNIQUE_QUANTITIES_${name})
    foreach(quantity IN LISTS quantities)
      if(quantity IN_LIST declared)
        message(FATAL_ERROR "techniques/${name}: QUANTITIES ${quantity}, which is declared twice "
                            "(by another technique, or in GTLAB_SHARED_QUANTITIES)")
      endif()
      list(APPEND declared ${quantity})
    endforeach()
  endforeach()
  set(ordered)
  foreach(quantity IN LISTS order)
    if(NOT quantity IN_LIST declared)
      message(FATAL_ERROR "GTLAB_QUANTITY_ORDER names ${quantity}, which no technique declares")
    endif()
    list(APPEND ordered ${quantity})
  endforeach()
  foreach(quantity IN LISTS declared)
    if(NOT quantity IN_LIST ordered)
      list(APPEND ordered ${quantity})
    endif()
  endforeach()
  set(${out_var} ${ordered} PARENT_SCOPE)
endfunction()
