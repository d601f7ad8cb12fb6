// Tiling cases: their printing as C++ initialisers, and their vertices through clip space and snapping.
#include "properties/generators/tiling_case.h"

#include "properties/printing.h"

namespace raster::properties {
namespace {

std::string describe_points(const std::vector<glm::dvec2>& points) {
    std::string s = "{";
    for (size_t i = 0; i < points.size(); ++i) s += (i ? ", " : "") + literal(points[i]);
    return s + "}";
}

}  // namespace

std::ostream& operator<<(std::ostream& os, const TilingCase& c) {
    os << "TilingCase{\"" << c.kind << "\", " << c.frame << ", ScreenMesh{" << describe_points(c.mesh.vertices) << ", {";
    for (size_t i = 0; i < c.mesh.w.size(); ++i) os << (i ? ", " : "") << float_literal(c.mesh.w[i]);
    os << "}, {";
    for (size_t i = 0; i < c.mesh.triangles.size(); ++i)
        os << (i ? ", " : "") << "{" << c.mesh.triangles[i][0] << ", " << c.mesh.triangles[i][1] << ", "
           << c.mesh.triangles[i][2] << "}";
    os << "}, {";
    for (size_t i = 0; i < c.mesh.outline.size(); ++i) os << (i ? ", " : "") << c.mesh.outline[i];
    os << "}, {";
    for (size_t i = 0; i < c.mesh.interior.size(); ++i) os << (i ? ", " : "") << c.mesh.interior[i];
    return os << "}}}";
}

std::vector<reference::Point> snapped_vertices(const Frame& frame, const ScreenMesh& mesh) {
    std::vector<reference::Point> v;
    for (size_t i = 0; i < mesh.vertices.size(); ++i) v.push_back(snapped(frame, clip_from_screen(frame, mesh.vertices[i], mesh.w[i])));
    return v;
}

std::vector<ClipTriangle> clip_triangles(const Frame& frame, const ScreenMesh& mesh) {
    std::vector<ClipTriangle> out;
    for (const auto& t : mesh.triangles) {
        ClipTriangle c;
        for (int i = 0; i < 3; ++i) {
            const auto v = static_cast<size_t>(t[static_cast<size_t>(i)]);
            c.v[static_cast<size_t>(i)] = clip_from_screen(frame, mesh.vertices[v], mesh.w[v]);
        }
        out.push_back(c);
    }
    return out;
}

}  // namespace raster::properties
