// The front end both renderers run first: the vertex stage, then clipping and setup of every triangle in draw
// order, each counted and timed into the frame's statistics.
#pragma once

#include <vector>

#include "raster/pipeline/frame.h"
#include "raster/pipeline/frame_params.h"
#include "raster/pipeline/resolve.h"
#include "raster/pipeline/shadow_maps.h"
#include "raster/pipeline/stages.h"
#include "raster/pipeline/vertex_stage.h"

namespace raster {

// The vertex stage, for the attributes the scene's shading needs; counts triangles and times ms_vertex.
TransformedScene run_vertex_stage_timed(const Scene& scene, const PipelineStages& stages, RenderStats& stats);

// Culls (when cull_backfaces), clips and sets up the vertex stage's triangles in parallel chunks, kept in draw
// order, into workspace.setup_chunks (kSetupChunkTriangles scene triangles a chunk); counts clipped and rasterized
// triangles. The caller times it.
void set_up_triangles_into(const TransformedScene& geometry, const FrameParams& frame, const PipelineStages& stages,
                           bool cull_backfaces, RenderStats& stats, RenderWorkspace& workspace);

// The chunks' setups one after the other, into `out` (its old contents replaced), copied on `threads` threads.
void concatenate_setups(const std::vector<std::vector<TriangleSetup>>& chunks, int threads,
                        std::vector<TriangleSetup>& out);

// set_up_triangles_into's setups in one fresh vector.
std::vector<TriangleSetup> set_up_triangles(const TransformedScene& geometry, const FrameParams& frame,
                                            const PipelineStages& stages, bool cull_backfaces, RenderStats& stats);

// What the front end hands a renderer: the vertex stage's output and the frame; the setups are in the result's
// workspace, the opaque ones in setup_chunks and the transparent ones in transparent_setups.
struct FrontEnd {
    TransformedScene geometry;
    FrameParams frame;
};

// A frame's start, for either renderer: resets result.stats, runs the vertex stage and sets up every triangle
// (timing ms_vertex and ms_setup) for the frame the scene and the options ask for.
FrontEnd run_front_end(const Scene& scene, const RenderOptions& options, const PipelineStages& stages,
                       RenderResult& result);

// The shadow maps the frame needs (none unless a light casts shadows and the shading is lit), rendered with the
// frame's stages and renderer; times ms_shadow.
ShadowMaps build_shadow_maps(const Scene& scene, const FrontEnd& front, const RenderOptions& options,
                             const PipelineStages& stages, RenderStats& stats);

// The transparency pass (transparency.h) over the frame just resolved into result.image from result.visibility,
// when the front end set aside transparent setups; times ms_transparency.
void composite_transparency_timed(const Scene& scene, const FrontEnd& front, const Shader& shader,
                                  const ResolveParams& resolve, RenderResult& result);

// The resolve parameters the scene's settings and the options ask for.
ResolveParams resolve_params_for(const Scene& scene, const RenderOptions& options);

}  // namespace raster
