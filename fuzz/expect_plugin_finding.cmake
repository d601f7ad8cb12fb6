# The differential target finds the example naive plugin's bugs (examples/naive_plugin, docs/plugins.md): run as
#   cmake -DFUZZER=<differential_fuzzer> -DPLUGIN=<libnaive_rasterizer.so> -DCORPUS=<folder> -P expect_plugin_finding.cmake
# It replays the differential corpus against the plugin and requires the target to stop on a genuine disagreement
# that the comparison attributes to the plugin, not on anything else.
foreach(var FUZZER PLUGIN CORPUS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "expect_plugin_finding.cmake: -D${var}=... is required")
  endif()
endforeach()
set(ENV{RASTER_FUZZ_PLUGIN} ${PLUGIN})
execute_process(COMMAND ${FUZZER} ${CORPUS} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out
                TIMEOUT 600)
if(status EQUAL 0)
  message(FATAL_ERROR "the differential target replayed its corpus against the naive plugin and found nothing\n${out}")
endif()
foreach(expected "check failed: genuine == uint64_t{0}" "(plugin naive rasterizer")
  string(FIND "${out}" "${expected}" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "the differential target stopped (${status}), but its report lacks '${expected}':\n${out}")
  endif()
endforeach()
message(STATUS "the differential target found the naive plugin's bug:\n${out}")
