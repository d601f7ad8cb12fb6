// Every generator of the property suite, in one place. Each mixes random cases with hand-picked extremes through
// rc::gen::weightedOneOf and names its kind, so that the properties' RC_CLASSIFY shows the mix.
#pragma once

#include <array>
#include <ostream>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <rapidcheck.h>

#include "properties/stage_driver.h"
#include "mutants/building_blocks.h"

namespace raster::properties {

// --- screen-space meshes (coverage, watertightness, fill rule, sampling) -------------------------------------

// A triangulated region in screen space. Vertices are on the frame's exact grid, so they land exactly where they
// are put; w is each vertex's view depth (a power of two, so the vertex stays exact under perspective).
struct ScreenMesh {
    std::vector<glm::dvec2> vertices;
    std::vector<float> w;
    std::vector<std::array<int, 3>> triangles;  // drawing order and winding as generated
    std::vector<int> outline;                   // the union's boundary when it is strictly convex, else empty
    std::vector<int> interior;                  // vertices inside the union (every way out crosses a triangle)
};

struct TilingCase {
    std::string kind;
    Frame frame;
    ScreenMesh mesh;
};
std::ostream& operator<<(std::ostream& os, const TilingCase& c);

// The mesh's triangles in clip space (depth 0.5, each vertex at its own w).
std::vector<ClipTriangle> clip_triangles(const Frame& frame, const ScreenMesh& mesh);

// The mesh's vertices where setup puts them: through clip space, the divide, the viewport and snapping.
std::vector<reference::Point> snapped_vertices(const Frame& frame, const ScreenMesh& mesh);

rc::Gen<TilingCase> convex_polygon_fans();       // random convex polygons split into fans, any orientation/offset
rc::Gen<TilingCase> jittered_grids();            // grids of quads, inner vertices jittered, split either way
rc::Gen<TilingCase> triangle_strips();           // strips between two rails
rc::Gen<TilingCase> pairs_sharing_an_edge_through_samples();  // the shared edge passes exactly through samples
rc::Gen<TilingCase> fans_around_a_sample();      // the shared vertex is exactly a sample
rc::Gen<TilingCase> single_triangles();          // random, axis-aligned, slivers, tiny, around samples, off-grid
rc::Gen<TilingCase> symmetric_pairs_sharing_an_edge();  // as above, on frames whose sample pattern is symmetric
rc::Gen<TilingCase> grid_sampled_triangles();    // one triangle on a frame with an N x N grid pattern
rc::Gen<TilingCase> sliver_pairs();              // two slivers of aspect ~1e6 sharing their long edge
rc::Gen<TilingCase> sub_pixel_triangles();       // triangles smaller than 1/256 px, and ones under 1 px^2 on a sample

// The linear part of a symmetry of the square frame (a signed permutation matrix, rows as {xx, xy, yx, yy}).
struct FrameSymmetry {
    std::string name;
    int m[4];
};
std::ostream& operator<<(std::ostream& os, const FrameSymmetry& g);
const std::vector<FrameSymmetry>& square_symmetries();  // the seven non-identity mirrors and quarter turns
glm::dvec2 apply(const FrameSymmetry& g, const Frame& frame, const glm::dvec2& screen);

// --- clip space ----------------------------------------------------------------------------------------------

// One triangle in clip space on a frame with a clip volume.
struct ClipCase {
    std::string kind;
    Frame frame;
    ClipTriangle triangle;
};
std::ostream& operator<<(std::ostream& os, const ClipCase& c);

rc::Gen<ClipCase> perspective_triangles_inside();   // inside the frustum, vertices at different view depths
rc::Gen<ClipCase> triangles_inside_the_volume();    // inside or exactly on its planes (near, far, sides)
rc::Gen<ClipCase> triangles_crossing_the_volume();  // behind the eye, across near/far/sides, far off screen, w ~ 0
rc::Gen<ClipCase> triangles_far_off_screen();       // vertices up to 2^20 pixels off screen
rc::Gen<ClipCase> triangles_with_w_near_zero();     // a vertex with w = 0, +-denormal, +-1e-30, +-near * 1e-7
rc::Gen<ClipCase> triangles_with_non_finite_coordinates();  // NaN or +-Inf in one to three coordinates

// --- view space ----------------------------------------------------------------------------------------------

// Triangles in view space (camera at the origin looking down -z), seen through a 90 degree lens.
struct ViewTriangle {
    std::array<glm::vec3, 3> v;
};
struct LayeredCase {
    std::string kind;
    Frame frame;
    std::vector<ViewTriangle> triangles;
    std::vector<int> order;  // a permutation of the triangles, for draw-order checks
};
std::ostream& operator<<(std::ostream& os, const LayeredCase& c);

rc::Gen<LayeredCase> overlapping_triangles();      // at distinct depths, tilted, or intersecting each other
rc::Gen<LayeredCase> fronto_parallel_layers();     // each triangle at its own power-of-two depth: no ties anywhere
rc::Gen<LayeredCase> triangles_touching_the_near_plane();  // one triangle, one to three vertices exactly at w = near

// --- matrices and lenses -------------------------------------------------------------------------------------

struct CameraCase {
    std::string kind;
    glm::vec3 eye, target, up;
};
std::ostream& operator<<(std::ostream& os, const CameraCase& c);
rc::Gen<CameraCase> cameras();  // random, far from the origin, very close target, up nearly parallel, long up

struct LensCase {
    std::string kind;
    float fov_y_degrees = 45.0f, aspect = 1.0f, near = 0.1f, far = 100.0f;
    int width = 640, height = 480;  // an image with this aspect (approximately, for the border checks)
    float depth = 1.0f;             // a view depth in [near, far]
    float farther = 2.0f;           // a second one, > depth * (1 + 2^-19), in (depth, far]
    glm::vec2 across{0.0f};         // a point of the frustum's cross-section, in [-1, 1]^2
};
std::ostream& operator<<(std::ostream& os, const LensCase& c);
rc::Gen<LensCase> lenses();  // random, near = 1e-6 and far = 1e9, far = near (1 + 2^-10), fov 1 and 179 degrees

struct ModelCase {
    std::string kind;
    mutants::ScaleRotateTranslate chain;
    std::array<glm::vec3, 3> triangle;  // object space
};
std::ostream& operator<<(std::ostream& os, const ModelCase& c);
rc::Gen<ModelCase> models();  // non-uniform and mirrored scales from 1e-3 to 1e3, any rotation, far translations

// --- extremes of whole scenes --------------------------------------------------------------------------------

struct DepthPairCase {
    std::string kind;
    float near_depth, far_depth;  // two fronto-parallel quads, near_depth < far_depth, over near = 1e-6, far = 1e9
    bool nearer_first;
};
std::ostream& operator<<(std::ostream& os, const DepthPairCase& c);
rc::Gen<DepthPairCase> depth_pairs_over_extreme_range();

struct ScaledSceneCase {
    std::string kind;
    int exponent;                         // the scene is scaled by 2^exponent
    std::array<glm::vec3, 3> triangle;    // world space, in front of the camera
    glm::vec3 eye, target;
    float near, far;
};
std::ostream& operator<<(std::ostream& os, const ScaledSceneCase& c);
rc::Gen<ScaledSceneCase> scenes_scaled_towards_float_limits();

// --- lighting -----------------------------------------------------------------------------------------------

struct LightCase {
    std::string kind;
    glm::vec3 normal;     // unit
    glm::vec3 direction;  // unit, from the point towards the light, n . direction > 0
    float distance;
    glm::vec3 color;
};
std::ostream& operator<<(std::ostream& os, const LightCase& c);
rc::Gen<LightCase> lights();

// --- small helpers the properties share -----------------------------------------------------------------------

// A random permutation of 0 .. n-1.
rc::Gen<std::vector<int>> permutations(int n);

}  // namespace raster::properties
