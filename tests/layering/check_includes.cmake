# Fails when a source file has a quoted include that is not a path from the project root into a module folder
# (raster/<module>/, oracle/<module>/, harness/<module>/, backends/<backend>/, apps/, mutants/, properties/, fuzz/,
# bench/, tools/, tests/support/), since such an include is found next to the including file and gets around the
# modules' include views.
file(GLOB_RECURSE sources RELATIVE ${ROOT}
  ${ROOT}/raster/*.h ${ROOT}/raster/*.cpp ${ROOT}/oracle/*.h ${ROOT}/oracle/*.cpp ${ROOT}/harness/*.h ${ROOT}/harness/*.cpp ${ROOT}/backends/*.h ${ROOT}/backends/*.cpp ${ROOT}/apps/*.h ${ROOT}/apps/*.cpp
  ${ROOT}/properties/*.h ${ROOT}/properties/*.cpp ${ROOT}/fuzz/*.h
  ${ROOT}/fuzz/*.cpp ${ROOT}/bench/*.h ${ROOT}/bench/*.cpp ${ROOT}/tools/*.h ${ROOT}/tools/*.cpp ${ROOT}/tests/*.h
  ${ROOT}/tests/*.cpp ${ROOT}/mutants/*.h ${ROOT}/mutants/*.cpp)
# The schemata build's switch is included by the generated copies of raster's sources through that build's own
# include path (cmake/mutant_schemata.cmake), with its generated site table: it has no module folder to name.
list(FILTER sources EXCLUDE REGEX "^mutants/switch/")
set(roots "raster/(core|scene|transform|formats|gltf|compat|image|texture|simd|geometry|rasterize|shading|resolve|frame)/|oracle/(reference|compare|report)/|harness/(comparison|grading|tradeoff)/|backends/(gl|plugin)/|apps/|mutants/|properties/|fuzz/|bench/|tools/|tests/support/")
set(problems "")
foreach(source IN LISTS sources)
  file(STRINGS ${ROOT}/${source} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]*)\".*" "\\1" header "${line}")
    if(NOT header MATCHES "^(${roots})[A-Za-z0-9_/]+\\.h$" OR header MATCHES "\\.\\.")
      string(APPEND problems "${source}: #include \"${header}\" is not a module header named from the project root\n")
    elseif(NOT EXISTS ${ROOT}/${header})
      string(APPEND problems "${source}: #include \"${header}\" names no file\n")
    endif()
  endforeach()
endforeach()
list(LENGTH sources count)
if(problems)
  message(FATAL_ERROR "${problems}")
endif()
message(STATUS "check_includes: the quoted includes of ${count} files all name module headers from the root")
