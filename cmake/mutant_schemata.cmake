# The mutant schemata build (-DRASTER_MUTANT_SCHEMATA=ON): every entry of mutants/bugs.txt compiled into raster
# behind a runtime switch (RASTER_MUTANT=name), so that one build holds every planted bug. raster_mutants generate
# writes a copy of each source file that has entries into build/mutant_schemata/, with each find text turned into
# a switch between the correct code and the bug; the module targets compile the copies instead of the originals,
# and a module's include view (cmake/raster_module.cmake) shows the copies of its headers in place of the originals.
# The source tree itself is never modified.
#
# No include directory and no definition is added: every other file compiles with the production build's own
# command line and headers, so that when a production build turns into the schemata build in place (tools/
# plant_bugs.sh --reuse-build), ninja leaves those files alone and only the copies and the files including a header
# copy compile.
#
#   raster_mutant_schemata_apply()      after every target exists: swaps the sources and the header views, adds
#                                       the switch
#   raster_mutant_schemata_leftovers()  in a normal build: clears what a schemata build left in its folder
set(RASTER_MUTANT_SCHEMATA_DIR ${PROJECT_BINARY_DIR}/mutant_schemata)

# Every object of the build removed, saying why. Needed wherever a file the objects compiled is seen again as an
# original older than they are (a header copy gone from an include view), which nothing would recompile; ccache gives
# back those it cached (the files without a precompiled header, or every file with
# CCACHE_SLOPPINESS=pch_defines,time_macros).
function(raster_remove_build_objects why)
  file(GLOB_RECURSE objects ${PROJECT_BINARY_DIR}/*.o)
  if(objects)
    file(REMOVE ${objects})
  endif()
  message(STATUS "${why}: removed the build's objects")
endfunction()

# A normal build that was a schemata build (tools/plant_bugs.sh --reuse-build) compiles the production sources again.
function(raster_mutant_schemata_leftovers)
  if(EXISTS ${RASTER_MUTANT_SCHEMATA_DIR})
    raster_remove_build_objects("This build was a mutant schemata build")
    file(REMOVE_RECURSE ${RASTER_MUTANT_SCHEMATA_DIR})
  endif()
endfunction()

# The include view of raster/MODULE (a link to the source folder) becomes a folder of links, one per file, the
# header copies among them linking to their copies.
function(raster_mutant_header_view module copies)
  set(view ${PROJECT_BINARY_DIR}/include_views/raster_${module}/raster/${module})
  if(NOT IS_SYMLINK ${view})
    message(FATAL_ERROR "${view} is not raster_${module}'s include view link")
  endif()
  file(REMOVE ${view})
  if(IS_SYMLINK ${view} OR EXISTS ${view})
    # Never write links through it: it leads into the source folder.
    message(FATAL_ERROR "cannot remove ${view}, raster_${module}'s include view link")
  endif()
  file(MAKE_DIRECTORY ${view})
  # Re-globbed at every build: a header added to the module reaches the view.
  file(GLOB entries CONFIGURE_DEPENDS RELATIVE ${PROJECT_SOURCE_DIR}/raster/${module}
       ${PROJECT_SOURCE_DIR}/raster/${module}/*)
  foreach(entry IN LISTS entries)
    set(target ${PROJECT_SOURCE_DIR}/raster/${module}/${entry})
    if("raster/${module}/${entry}" IN_LIST copies)
      set(target ${RASTER_MUTANT_SCHEMATA_DIR}/raster/${module}/${entry})
    endif()
    file(CREATE_LINK ${target} ${view}/${entry} SYMBOLIC)
  endforeach()
endfunction()

# Every target defined under DIR (recursively) into the variable OUT.
function(raster_targets_under dir out)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirectories DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(subdirectory IN LISTS subdirectories)
    raster_targets_under(${subdirectory} more)
    list(APPEND targets ${more})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

function(raster_mutant_schemata_apply)
  set(catalogue ${PROJECT_SOURCE_DIR}/mutants/bugs.txt)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${catalogue})
  file(STRINGS ${catalogue} file_lines REGEX "^file[ \t]*=")
  set(files)
  foreach(line IN LISTS file_lines)
    string(REGEX REPLACE "^file[ \t]*=[ \t]*" "" file "${line}")
    string(STRIP "${file}" file)
    list(APPEND files ${file})
  endforeach()
  list(REMOVE_DUPLICATES files)
  set(outputs ${RASTER_MUTANT_SCHEMATA_DIR}/raster_mutant_sites.h)
  set(originals)
  foreach(file IN LISTS files)
    list(APPEND outputs ${RASTER_MUTANT_SCHEMATA_DIR}/${file})
    list(APPEND originals ${PROJECT_SOURCE_DIR}/${file})
  endforeach()
  add_custom_command(OUTPUT ${outputs}
    COMMAND raster_mutants --root ${PROJECT_SOURCE_DIR} generate --out ${RASTER_MUTANT_SCHEMATA_DIR}
    DEPENDS raster_mutants ${catalogue} ${originals}
    COMMENT "Writing the mutant schemata sources from mutants/bugs.txt")
  add_custom_target(raster_mutant_schemata_sources DEPENDS ${outputs})

  # The switch, linked through raster_core so that every program linking a module (and so a copy) links it. The
  # copies include its header by its absolute path; nothing else sees its include directories.
  add_library(raster_mutant_switch STATIC ${PROJECT_SOURCE_DIR}/mutants/switch/raster_mutant_switch.cpp)
  target_include_directories(raster_mutant_switch PRIVATE ${PROJECT_SOURCE_DIR}/mutants/switch
                                                           ${RASTER_MUTANT_SCHEMATA_DIR})
  target_link_libraries(raster_core PRIVATE raster_mutant_switch)

  # Each header copy replaces its original in its module's include view.
  set(headers)
  foreach(file IN LISTS files)
    if(file MATCHES "^raster/([a-z_]+)/[^/]+\\.h$")
      list(APPEND headers ${file})
      list(APPEND header_modules ${CMAKE_MATCH_1})
    endif()
  endforeach()
  if(header_modules)
    list(REMOVE_DUPLICATES header_modules)
  endif()
  foreach(module IN LISTS header_modules)
    raster_mutant_header_view(${module} "${headers}")
  endforeach()
  # A header that had a copy and has none now is seen through the view as its original again.
  set(header_list ${RASTER_MUTANT_SCHEMATA_DIR}/header_copies.txt)
  if(EXISTS ${header_list})
    file(STRINGS ${header_list} previous_headers)
    foreach(header IN LISTS previous_headers)
      if(NOT header IN_LIST headers)
        raster_remove_build_objects("${header} has no copy any more")
        break()
      endif()
    endforeach()
  endif()
  string(REPLACE ";" "\n" header_text "${headers}")
  file(WRITE ${header_list} "${header_text}\n")

  # Each source file's module compiles its copy, with the original's compile options.
  foreach(file IN LISTS files)
    if(NOT file MATCHES "\\.cpp$")
      if(NOT file MATCHES "^raster/[a-z_]+/[^/]+\\.h$")
        message(FATAL_ERROR "mutants/bugs.txt plants into ${file}, which is neither a module's source nor its header")
      endif()
      continue()  # a header: its copy replaced the original in the include view above
    endif()
    # raster/NAME/ is the module raster_NAME; backends/NAME/ the backend raster_backend_NAME.
    if(file MATCHES "^raster/([a-z_]+)/")
      set(target raster_${CMAKE_MATCH_1})
      set(folder ${PROJECT_SOURCE_DIR}/raster/${CMAKE_MATCH_1})
    elseif(file MATCHES "^backends/([a-z_]+)/")
      set(target raster_backend_${CMAKE_MATCH_1})
      set(folder ${PROJECT_SOURCE_DIR}/backends/${CMAKE_MATCH_1})
    else()
      message(FATAL_ERROR "mutants/bugs.txt plants into ${file}, which is in no raster module or backend")
    endif()
    get_target_property(sources ${target} SOURCES)
    get_filename_component(name ${file} NAME)
    list(FIND sources ${name} at)
    if(at LESS 0)
      message(FATAL_ERROR "mutants/bugs.txt plants into ${file}, which ${target} does not compile")
    endif()
    list(REMOVE_AT sources ${at})
    list(INSERT sources ${at} ${RASTER_MUTANT_SCHEMATA_DIR}/${file})
    set_property(TARGET ${target} PROPERTY SOURCES ${sources})
    get_source_file_property(options ${folder}/${name} DIRECTORY ${folder} COMPILE_OPTIONS)
    if(options)
      set_source_files_properties(${RASTER_MUTANT_SCHEMATA_DIR}/${file} DIRECTORY ${folder}
        PROPERTIES COMPILE_OPTIONS "${options}")
    endif()
  endforeach()

  # Every target waits for the copies, since any of them may include a header copy.
  raster_targets_under(${PROJECT_SOURCE_DIR} targets)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "INTERFACE_LIBRARY" OR target MATCHES "^(raster_mutants|raster_mutant_catalogue|raster_mutant_schemata_sources)$")
      continue()
    endif()
    add_dependencies(${target} raster_mutant_schemata_sources)
  endforeach()
endfunction()
