// What a correct shadow map may answer for a footprint of face pixels (shadow_precision.h), decided from the
// exact geometry the map is rendered from: every opaque triangle seen from the light on each cube face, clipped and
// projected in double (reference_geometry.h, with the face's camera), with its edges marked where they can bound
// the occluders' union (silhouette and open edges). docs/shadows.md gives the map; precision.h part 10 the model.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "oracle/reference/interval.h"
#include "oracle/reference/reference_geometry.h"
#include "oracle/reference/scene_geometry.h"
#include "oracle/reference/shadow_faces.h"
#include "oracle/reference/shadow_precision.h"
#include "raster/scene/scene.h"

namespace raster::oracle {

// The map's answer over a footprint, for a receiver whose reference depth (depth - bias) is in an interval:
enum class MapAnswer : uint8_t {
    lit,         // no surface nearer than the reference anywhere in the footprint: every tap passes
    shadowed,    // occluders nearer than the reference cover the whole footprint: every tap fails
    open_edge,   // an occluder's silhouette (or open) edge crosses the footprint, within its precision: any fraction
    open_depth,  // a surface's depth meets the reference somewhere in the footprint, within precision: any fraction
};

class ShadowIndex {
public:
    // Light `light` of `scene`, whose world positions are geometry.world. `casts(id)` says which triangles are in
    // the map (the opaque ones).
    ShadowIndex(const Scene& scene, const OracleScene& geometry, size_t light, const std::vector<uint8_t>& casts);
    ~ShadowIndex();

    // The map's answer at the texel centres in `taps` for a receiver whose reference depth is in `reference`.
    MapAnswer answer(int face, const TexelRect& taps, const Interval& reference) const;
    // Whether a boundary edge of a surface that is nearer the light than `depth` somewhere crosses the footprint,
    // within its precision: what can make the taps' answer differ from the point's own direction's.
    bool occluder_edge_within(int face, const TexelRect& footprint, double depth) const;
    const ShadowPlanes& planes() const { return planes_; }

private:
    struct Face;
    // What each_candidate tells of a triangle that meets a region widened by its radius.
    struct SurfaceRange {
        bool bounded = true;             // false: its depth there is unknown (the light sees it edge-on)
        double nearest = 0, farthest = 0;  // the map's depth of it anywhere in the region
        bool inside = false;             // it meets the region itself, not only the widening
        uint16_t boundary = 0;           // which of its polygon's edges can bound the occluders
    };
    // Calls visit(id, polygon vertices, widened region, range) for every triangle on `face` that meets the region
    // widened by its radius, until visit returns false.
    template <class Visit>
    void each_candidate(int face, const TexelRect& region, Visit visit) const;
    ShadowPlanes planes_;
    std::vector<std::unique_ptr<Face>> faces_;
};

// Which edges of which triangles can bound the union of occluders seen from `light`: an edge is interior when
// exactly two triangles of the same mesh share it (their vertices at the same positions: raster's map is
// watertight there) and they lie on opposite sides of the plane through the light and the edge (both face the
// light the same way); every other edge (a silhouette, an open or non-manifold edge, a degenerate triangle's) is a
// boundary. Only triangles with `casts` set count (a shared edge with one that casts no shadow is a boundary).
// Bit k of entry t: the edge from vertex k to vertex k + 1 of triangle t is a boundary.
std::vector<uint8_t> boundary_edges(const Scene& scene, const OracleScene& geometry, const glm::dvec3& light,
                                    const std::vector<uint8_t>& casts);

}  // namespace raster::oracle
