// The rasterizer's stages as the functions a property calls, so that each property drives one stage on its own
// hand-made input (stage_driver.h). Always the production functions: a bug of the catalogue is planted into the
// source itself (mutants/bugs.txt), and production never reads this struct.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "raster/geometry/clip.h"
#include "raster/geometry/frame_params.h"
#include "raster/shading/lighting.h"
#include "raster/rasterize/reference_rasterizer.h"
#include "raster/geometry/sample_pattern.h"
#include "raster/geometry/setup.h"
#include "raster/geometry/vertex_stage.h"

namespace raster::properties {

struct StageFunctions {
    TransformedScene (*vertex)(const Scene&, const VertexStageNeeds&) = run_vertex_stage;  // camera matrices
    ClippedPolygon (*clip)(const glm::vec4&, const glm::vec4&, const glm::vec4&, const ClipVolume&) = clip_triangle;
    int (*setup)(const ClippedPolygon&, uint32_t, const FrameParams&, std::vector<TriangleSetup>&) = setup_polygon;
    // Coverage and depth of the reference rasterizer (Backend reference); the tiled ones are rasterize_tiled's.
    void (*reference_rasterize)(const std::vector<TriangleSetup>&, const FrameParams&, VisibilityBuffer&) =
        rasterize_reference;
    std::vector<glm::vec2> (*sample_offsets)(int, SamplePattern) = raster::sample_offsets;
    LightingTerms (*lighting)(const glm::vec3&, const glm::vec3&, const glm::vec3&, const Material&,
                              const std::vector<Light>&, const glm::vec3&, SpecularModel, const float*) =
        evaluate_lighting;
};

}  // namespace raster::properties
