# What the renderer properties find in the example naive plugin (examples/naive_plugin, docs/plugins.md): run as
#   cmake -DPROPERTIES=<raster_properties_test> -DPLUGIN=<libnaive_rasterizer.so> -P expect_plugin_findings.cmake
# It runs every renderer property on the plugin and requires each of its bugs to fail the properties that check
# for it, with the failure that names the bug, and the properties its bugs do not touch to pass, so that neither a
# property that stopped seeing the bug nor one that fails on anything goes unnoticed.
foreach(var PROPERTIES PLUGIN)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "expect_plugin_findings.cmake: -D${var}=... is required")
  endif()
endforeach()
set(ENV{RASTER_PROPERTIES_PLUGIN} ${PLUGIN})
execute_process(COMMAND ${PROPERTIES} --gtest_filter=*/plugin RESULT_VARIABLE status OUTPUT_VARIABLE out
                ERROR_VARIABLE out TIMEOUT 600)
if(status EQUAL 0)
  message(FATAL_ERROR "every renderer property passed on the naive plugin: they no longer find its bugs\n${out}")
endif()

# Each bug, the properties it fails and what their failure says.
set(failing
  # No fill rule: a shared edge's samples covered by both triangles, a shared vertex's by all of its fan.
  "FillRule.ownershipChangesUnderMirrorsAndQuarterTurnsAsTheRuleSays|covered by both triangles"
  "Coverage.sharedVertexOnASampleCoveredExactlyOnce|is covered 3 times"
  # Float edges on unsnapped vertices: samples the snapped triangle does not hold, and cracks and overlaps.
  "Coverage.coveredSamplesEqualTheExactIntegerReference|the exact reference says"
  "Watertight.jitteredGridsCoverEverySampleOfTheirRectangleExactlyOnce|is covered 2 times"
  "Extremes.sliversOfAspectOneMillionAreWatertightAndExact|the exact reference says"
  # Affine barycentrics: off the sample, and off the perspective-correct ray's hit.
  "Barycentrics.reproduceTheSampleScreenPosition|reproduce"
  "Barycentrics.perspectiveCorrectOnesReproduceTheRayPlaneIntersection|ray")
set(passing
  "Depth.exactTiesKeepTheEarlierTriangle"
  "Depth.imageDoesNotDependOnDrawOrderWithoutTies"
  "Barycentrics.areNonNegativeOnCoveredSamples"
  "Sampling.gridCoverageConvergesToTheExactAreaWithinAPerimeterBound")

set(problems "")
foreach(entry IN LISTS failing)
  string(REPLACE "|" ";" parts "${entry}")
  list(GET parts 0 name)
  list(GET parts 1 says)
  string(FIND "${out}" "[  FAILED  ] ${name}/plugin (" failed)
  if(failed EQUAL -1)
    string(APPEND problems "  ${name} did not fail on the naive plugin\n")
    continue()
  endif()
  # The failure's own message, between its RUN line and its FAILED line.
  string(FIND "${out}" "[ RUN      ] ${name}/plugin" begin)
  string(SUBSTRING "${out}" ${begin} -1 rest)
  string(FIND "${rest}" "[  FAILED  ] ${name}/plugin (" length)
  string(SUBSTRING "${rest}" 0 ${length} report)
  string(FIND "${report}" "${says}" found)
  if(found EQUAL -1)
    string(APPEND problems "  ${name} failed, but not saying '${says}':\n${report}\n")
  endif()
endforeach()
foreach(name IN LISTS passing)
  string(FIND "${out}" "[       OK ] ${name}/plugin (" ok)
  if(ok EQUAL -1)
    string(APPEND problems "  ${name} did not pass on the naive plugin, which its bugs do not touch\n")
  endif()
endforeach()
if(problems)
  message(FATAL_ERROR "the renderer properties on the naive plugin:\n${problems}")
endif()
list(LENGTH failing failing_count)
list(LENGTH passing passing_count)
message(STATUS "naive plugin: ${failing_count} properties find its bugs, ${passing_count} that its bugs do not touch pass")
