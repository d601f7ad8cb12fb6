// The bug catalogue's list: each faulty variant (defined in the <stage>_faults.cpp of its stage) wraps or replaces
// exactly one real stage or building block, nothing else, and the list names its bug, stage and symptom.
#include "mutants/catalogue.h"

#include <stdexcept>

#include "mutants/clip_faults.h"
#include "mutants/lighting_faults.h"
#include "mutants/rasterize_faults.h"
#include "mutants/sample_position_faults.h"
#include "mutants/setup_faults.h"
#include "mutants/vertex_faults.h"

namespace raster::mutants {
namespace {

std::vector<Mutant> build_catalogue() {
    std::vector<Mutant> list;
    auto add = [&](const char* name, const char* stage, const char* symptom, auto&& replace) {
        Mutant m{name, stage, symptom, PipelineStages{}, BuildingBlocks{}};
        replace(m.stages);
        list.push_back(std::move(m));
    };
    // A fault in the reference rasterizer shows only on the reference renderer, the one that runs it.
    auto add_reference = [&](const char* name, const char* stage, const char* symptom, auto&& replace) {
        Mutant m{name, stage, symptom, PipelineStages{}, BuildingBlocks{}, RasterPath::reference};
        replace(m.stages);
        list.push_back(std::move(m));
    };
    auto add_block = [&](const char* name, const char* stage, const char* symptom, auto&& replace) {
        Mutant m{name, stage, symptom, PipelineStages{}, BuildingBlocks{}};
        replace(m.stages, m.blocks);
        list.push_back(std::move(m));
    };
    add("no near clipping", "clip", "vertices behind the eye reach the divide",
        [](PipelineStages& s) { s.clip = clip_without_near; });
    add("w <= 0 dropped instead of clipped", "clip", "triangles crossing the near plane vanish",
        [](PipelineStages& s) { s.clip = clip_dropping_near_crossers; });
    add("no fill rule", "setup", "samples on shared edges are covered twice",
        [](PipelineStages& s) { s.setup = setup_without_fill_rule; });
    add("cracks on shared edges", "setup", "samples on shared edges are covered by neither triangle",
        [](PipelineStages& s) { s.setup = setup_with_cracks; });
    add("sub-pixel triangles discarded", "setup", "triangles under one square pixel are dropped",
        [](PipelineStages& s) { s.setup = setup_discarding_sub_pixel; });
    add("y not flipped", "setup", "the image is upside down",
        [](PipelineStages& s) { s.setup = setup_without_y_flip; });
    add_reference("affine instead of perspective-correct", "rasterize",
                  "attributes interpolate linearly in screen space",
                  [](PipelineStages& s) { s.reference_rasterize = rasterize_affine; });
    add_reference("depth buffer initialised with numeric_limits<float>::min()", "rasterize",
                  "every fragment fails the depth test",
                  [](PipelineStages& s) { s.reference_rasterize = rasterize_with_depth_cleared_to_min; });
    add("wrong sample positions", "sample positions", "samples are half a pixel off",
        [](PipelineStages& s) { s.sample_offsets = sample_offsets_half_pixel_off; });
    add("integer-divided aspect ratio", "vertex", "the image is stretched horizontally",
        [](PipelineStages& s) { s.vertex = vertex_with_integer_aspect; });
    add("normals not transformed by the inverse-transpose", "vertex", "normals tilt under non-uniform scale",
        [](PipelineStages& s) { s.vertex = vertex_with_model_matrix_normals; });
    add("1/r^2 attenuation missing", "lighting", "attenuating lights shine at full strength",
        [](PipelineStages& s) { s.lighting = lighting_without_attenuation; });
    add("float edge functions", "setup", "edge equations rounded to float crack or double shared edges",
        [](PipelineStages& s) { s.setup = setup_with_float_edges; });
    add_block("model matrix multiplied in the wrong order", "model transform chain",
              "a scale-rotate-translate chain becomes S * R * T, so scaled objects fly off",
              [](PipelineStages&, BuildingBlocks& b) { b.model_matrix = model_matrix_composed_backwards; });
    add("front faces culled (winding inverted)", "setup", "with culling on, a closed mesh shows its inside",
        [](PipelineStages& s) { s.faces_front = faces_front_inverted; });
    add("fill rule inverted (bottom-right)", "setup", "shared samples go to the triangle below or right of the edge",
        [](PipelineStages& s) { s.setup = setup_with_bottom_right_rule; });
    add("side planes not clipped (vertices clamped instead)", "clip",
        "triangles reaching off screen are squashed against the border",
        [](PipelineStages& s) { s.clip = clip_without_side_planes; });
    add("near and far tested with a strict inequality", "clip",
        "a triangle touching the near or far plane is needlessly clipped",
        [](PipelineStages& s) { s.clip = clip_with_strict_near_far; });
    add("NaN slips through the clip test", "clip", "a triangle with a NaN vertex reaches setup and covers samples",
        [](PipelineStages& s) { s.clip = clip_letting_nan_through; });
    add_reference("view depth interpolated linearly (w instead of 1/w)", "rasterize",
                  "barycentrics do not sum to 1 and depths bulge away from the camera",
                  [](PipelineStages& s) { s.reference_rasterize = rasterize_with_linear_w; });
    add_reference("barycentrics evaluated at the pixel centre", "rasterize",
                  "samples near an edge extrapolate attributes (negative barycentrics)",
                  [](PipelineStages& s) { s.reference_rasterize = rasterize_with_pixel_centre_barycentrics; });
    add_reference("no depth test (the first triangle drawn stays)", "rasterize",
                  "draw order, not distance, decides visibility",
                  [](PipelineStages& s) { s.reference_rasterize = rasterize_without_depth_test; });
    add_block("look-at basis not orthonormal", "look-at matrix", "the view shears when up is not perpendicular",
              [](PipelineStages& s, BuildingBlocks& b) {
                  b.look_at = look_at_with_raw_up;
                  s.vertex = vertex_with_raw_up;
              });
    add_block("OpenGL [-1, 1] depth mapping", "projection matrix",
              "the z-buffer keeps the farthest surface and depth collapses at extreme near/far",
              [](PipelineStages& s, BuildingBlocks& b) {
                  b.perspective = perspective_with_opengl_depth;
                  s.vertex = vertex_with_opengl_depth;
              });
    return list;
}

}  // namespace

const std::vector<Mutant>& catalogue() {
    static const std::vector<Mutant> list = build_catalogue();
    return list;
}

const Mutant& mutant(const std::string& name) {
    for (const Mutant& m : catalogue())
        if (m.name == name) return m;
    throw std::out_of_range("no mutant named '" + name + "'");
}

}  // namespace raster::mutants
