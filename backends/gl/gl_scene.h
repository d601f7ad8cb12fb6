// The scene as the GL backend draws it: every triangle's three corners in world space (position, normal, base
// colour), in the scene's triangle order, cut into draws of one material each; and what the backend cannot draw.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "raster/scene/scene.h"

namespace raster::gl {

struct GlCorner {
    glm::vec3 position;  // world
    glm::vec3 normal;    // world, unit (zero where the scene gives none and none is needed)
    glm::vec3 colour;    // linear RGB: the face's, the vertex's or the material's
};

// Consecutive triangles of one material.
struct GlDraw {
    uint32_t first_corner = 0, corners = 0;
    const Material* material = nullptr;  // points into the scene
};

struct GlScene {
    std::vector<GlCorner> corners;  // 3 per triangle
    std::vector<GlDraw> draws;
};

// What of `scene` the backend cannot draw ("textures", "shadows", ...), one line; empty when it draws all of it.
std::string unsupported_by_gl(const Scene& scene);

// The nearest scene the backend draws (for the differential fuzzer, whose scenes ask for everything): its shading
// unlit, phong or blinn-phong (others become blinn-phong), 1 or 4 standard samples (more become 4), no MSAA, 8
// sub-pixel bits, the exact precision modes, no textures, blending or shadows, at most 8 lights. unsupported_by_gl
// of it is empty unless the frame is too large to read back or the near plane too close (finding 3).
Scene gl_drawable(Scene scene);

// The corners and draws of the valid `scene`. Missing normals are the average of the adjacent faces' unit normals
// in world space (docs/conventions.md "Lighting"); file normals go through the inverse transpose of the model matrix.
GlScene gl_scene(const Scene& scene);

}  // namespace raster::gl
