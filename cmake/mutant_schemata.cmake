# The mutant schemata build (-DRASTER_MUTANT_SCHEMATA=ON): every entry of mutants/bugs.txt compiled into raster
# behind a runtime switch (RASTER_MUTANT=name), so that one build holds every planted bug. raster_mutants generate
# writes a copy of each source file that has entries into build/mutant_schemata/, with each find text turned into
# a switch between the correct code and the bug; the module targets compile the copies instead of the originals,
# and the copies of headers come first on every include path. The source tree itself is never modified.
#
#   raster_mutant_schemata_prepare()  before the modules: the include path of the header copies
#   raster_mutant_schemata_apply()    after every target exists: swaps the sources, adds the switch
set(RASTER_MUTANT_SCHEMATA_DIR ${PROJECT_BINARY_DIR}/mutant_schemata)

macro(raster_mutant_schemata_prepare)
  include_directories(BEFORE ${RASTER_MUTANT_SCHEMATA_DIR})
endmacro()

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

  # The switch, linked by raster_core so that every module (and the generated copies) reaches it.
  add_library(raster_mutant_switch STATIC ${PROJECT_SOURCE_DIR}/mutants/switch/raster_mutant_switch.cpp)
  target_include_directories(raster_mutant_switch PUBLIC ${PROJECT_SOURCE_DIR}/mutants/switch
                                                          ${RASTER_MUTANT_SCHEMATA_DIR})
  target_link_libraries(raster_core PUBLIC raster_mutant_switch)

  # Each source file's module compiles its copy, with the original's compile options.
  foreach(file IN LISTS files)
    if(NOT file MATCHES "\\.cpp$")
      continue()  # a header: its copy comes first on the include path
    endif()
    if(NOT file MATCHES "^raster/([a-z_]+)/")
      message(FATAL_ERROR "mutants/bugs.txt plants into ${file}, which is in no raster module")
    endif()
    set(target raster_${CMAKE_MATCH_1})
    set(folder ${PROJECT_SOURCE_DIR}/raster/${CMAKE_MATCH_1})
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
