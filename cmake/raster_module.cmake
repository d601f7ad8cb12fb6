# raster_module: one folder of the project as one CMake target whose headers only its dependants can see.
#
#   raster_module(TARGET PATH folder [SOURCES file...] [PUBLIC target...] [PRIVATE target...])
#
# The folder's headers are included by their path from the project root ("raster/scene/scene.h"), but the project
# root is on no include path. Instead each module gets a folder of its own in the build tree that holds a single
# link, PATH -> the source folder, and that folder is the module's PUBLIC include directory. A target therefore
# sees the headers of its own module and of the modules it links (PUBLIC links pass theirs on), and nothing else:
# a frame file that includes "raster/formats/..." fails to compile with "No such file or directory", because
# raster_frame does not link raster_formats. Relative includes ("../formats/x.h") would get around this;
# tests/layering/ checks that no source uses one, and that the compiler refuses the forbidden includes.
function(raster_module target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "PATH" "SOURCES;PUBLIC;PRIVATE")
  if(NOT arg_PATH)
    message(FATAL_ERROR "raster_module(${target}): PATH is required")
  endif()
  set(view ${PROJECT_BINARY_DIR}/include_views/${target})
  get_filename_component(link_parent ${view}/${arg_PATH} DIRECTORY)
  file(MAKE_DIRECTORY ${link_parent})
  if(IS_DIRECTORY ${view}/${arg_PATH} AND NOT IS_SYMLINK ${view}/${arg_PATH})
    # A folder of links left by a mutant schemata build (cmake/mutant_schemata.cmake): links only, no sources.
    file(REMOVE_RECURSE ${view}/${arg_PATH})
  endif()
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${arg_PATH} ${view}/${arg_PATH} SYMBOLIC)
  if(arg_SOURCES)
    add_library(${target} STATIC ${arg_SOURCES})
    target_include_directories(${target} PUBLIC ${view})
    target_link_libraries(${target} PUBLIC ${arg_PUBLIC} PRIVATE ${arg_PRIVATE})
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE ${view})
    target_link_libraries(${target} INTERFACE ${arg_PUBLIC})
  endif()
endfunction()

# raster_include_view(TARGET PATH folder): the same view for a target that is not a library (a test executable
# whose own folder holds headers it includes by their full path).
function(raster_include_view target path)
  set(view ${PROJECT_BINARY_DIR}/include_views/${target})
  get_filename_component(link_parent ${view}/${path} DIRECTORY)
  file(MAKE_DIRECTORY ${link_parent})
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${path} ${view}/${path} SYMBOLIC)
  target_include_directories(${target} PRIVATE ${view})
endfunction()
