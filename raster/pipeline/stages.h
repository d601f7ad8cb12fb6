// The rasterizer's stages as one struct of functions, so the properties can drive each stage on its own hand-made
// input (properties/stage_driver.h) with exactly the functions render() runs.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "raster/pipeline/clip.h"
#include "raster/pipeline/frame_params.h"
#include "raster/pipeline/reference_rasterizer.h"
#include "raster/pipeline/sample_pattern.h"
#include "raster/pipeline/setup.h"
#include "raster/pipeline/shade.h"
#include "raster/pipeline/vertex_stage.h"

namespace raster {

// The stages render() runs: the real ones.
struct PipelineStages {
    TransformedScene (*vertex)(const Scene&, const VertexStageNeeds&) = run_vertex_stage;  // camera matrices
    bool (*faces_front)(const glm::vec4&, const glm::vec4&, const glm::vec4&) = raster::faces_front;  // culling
    ClippedPolygon (*clip)(const glm::vec4&, const glm::vec4&, const glm::vec4&, const ClipVolume&) = clip_triangle;
    int (*setup)(const ClippedPolygon&, uint32_t, const FrameParams&, std::vector<TriangleSetup>&) = setup_polygon;
    // Coverage and depth of the reference renderer only (RasterPath::reference): the tiled renderer has its own,
    // and refuses to run with this one replaced rather than silently switching renderer.
    void (*reference_rasterize)(const std::vector<TriangleSetup>&, const FrameParams&, VisibilityBuffer&) =
        rasterize_reference;
    std::vector<glm::vec2> (*sample_offsets)(int, SamplePattern) = raster::sample_offsets;
    LightingFunction lighting = evaluate_lighting;
};

}  // namespace raster
