# `cmake --install` into a fresh prefix gives a working tool: the installed raster prints its version, renders the
# installed teapot scene (its mesh found beside it) to the same bytes as the build's raster renders the corpus's,
# and the docs are in place. Arguments: BUILD (the build folder), PREFIX (a scratch folder), RASTER (the build's
# raster), SOURCE (the project root).
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX} RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed with ${status}")
endif()
foreach(path bin/raster share/doc/raster/README.md share/doc/raster/docs/install.md
             share/raster/examples/scenes/teapot.yaml share/raster/examples/meshes/teapot.obj)
  if(NOT EXISTS ${PREFIX}/${path})
    message(FATAL_ERROR "the install has no ${path}")
  endif()
endforeach()
execute_process(COMMAND ${PREFIX}/bin/raster --version RESULT_VARIABLE status OUTPUT_VARIABLE version)
if(NOT status EQUAL 0 OR NOT version MATCHES "^raster [0-9]+\\.[0-9]+\\.[0-9]+\n")
  message(FATAL_ERROR "the installed raster --version gave ${status}: ${version}")
endif()
execute_process(COMMAND ${PREFIX}/bin/raster render ${PREFIX}/share/raster/examples/scenes/teapot.yaml
                        -o ${PREFIX}/installed.png RESULT_VARIABLE status ERROR_VARIABLE error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the installed raster could not render the installed teapot (${status}): ${error}")
endif()
execute_process(COMMAND ${RASTER} render ${SOURCE}/corpus/scenes/teapot.yaml -o ${PREFIX}/built.png
                RESULT_VARIABLE status)
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${PREFIX}/installed.png ${PREFIX}/built.png
                RESULT_VARIABLE differs)
if(NOT status EQUAL 0 OR differs)
  message(FATAL_ERROR "the installed teapot's image differs from the build's")
endif()
file(REMOVE_RECURSE ${PREFIX})
