// The front end every frame and every shadow face runs first: culling, clipping and setup of the vertex stage's
// triangles in draw order, in parallel chunks, with the transparent triangles' setups set aside for their own pass.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "raster/geometry/frame_params.h"
#include "raster/geometry/setup.h"
#include "raster/geometry/vertex_stage.h"
#include "raster/scene/scene.h"

namespace raster {

// Each vertex of the frame projected to the screen once (setup.h), and whether it is inside the clip volume: the
// front end sets up a triangle of three inside vertices from these, without clipping it.
struct ProjectedVertices {
    std::vector<ScreenPoint> screen;
    std::vector<uint8_t> inside;
};

// What the front end hands the rasterizers. Its owner keeps it from frame to frame, so that its memory is reused
// instead of paged in fresh (tens of MB of triangle setups on an 80k-triangle mesh).
struct FrontEndSetups {
    ProjectedVertices projected;
    // The opaque triangles' setups (every triangle's in an opaque scene), chunk by chunk of kSetupChunkTriangles
    // scene triangles in draw order: the tiled renderer reads them in place (setup_table.h).
    std::vector<std::vector<TriangleSetup>> setup_chunks;
    std::vector<TriangleSetup> transparent_setups;  // the transparent triangles', in draw order (transparency.h)
};

struct SetupCounts {
    size_t clipped = 0;     // triangles that crossed a clip plane
    size_t rasterized = 0;  // setups made: screen triangles after clipping, fan splitting, culling and degeneracy
};

// Per scene triangle (in id order), 1 where its material is blended (is_blended); empty when no material is
// transparent, so an opaque scene does no per-triangle work for transparency.
std::vector<uint8_t> transparent_triangles(const Scene& scene);

// Culls (when cull_backfaces), clips and sets up the vertex stage's triangles in parallel chunks on frame.threads
// threads, kept in draw order, into out.setup_chunks; then moves the setups of the triangles `transparent` marks
// (transparent_triangles; empty: none) into out.transparent_setups.
SetupCounts set_up_triangles_into(const TransformedScene& geometry, const FrameParams& frame, bool cull_backfaces,
                                  const std::vector<uint8_t>& transparent, FrontEndSetups& out);

// Moves the setups of transparent triangles out of the chunks into `out` (cleared first): each chunk keeps its
// opaque setups, `out` gets every chunk's transparent ones, both in draw order.
void split_transparent_setups(const std::vector<uint8_t>& transparent,
                              std::vector<std::vector<TriangleSetup>>& chunks, std::vector<TriangleSetup>& out);

// The chunks' setups one after the other, into `out` (its old contents replaced), copied on `threads` threads.
void concatenate_setups(const std::vector<std::vector<TriangleSetup>>& chunks, int threads,
                        std::vector<TriangleSetup>& out);

// Every triangle's setups (none set aside) in one fresh vector, in draw order.
std::vector<TriangleSetup> set_up_triangles(const TransformedScene& geometry, const FrameParams& frame,
                                            bool cull_backfaces, SetupCounts* counts = nullptr);

}  // namespace raster
