# Regenerates the teapot OBJ from Newell's patches and checks it is byte-identical to the committed one.
execute_process(COMMAND ${TOOL} ${DATA} ${OUT} RESULT_VARIABLE status ERROR_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "tessellate_teapot failed with ${status}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${EXPECTED} RESULT_VARIABLE differs)
if(differs)
  message(FATAL_ERROR "${EXPECTED} differs from what tools/tessellate_teapot makes from ${DATA}")
endif()
