// Seed 001 (UCSD CSE 167 balboa, homework 2): the settings every balboa render shares, the camera-space triangle of
// part 2.1, and (through the scene loader) the JSON scenes of parts 2.2 to 2.4.
#pragma once

#include <array>
#include <string>

#include <glm/vec3.hpp>

#include "raster/scene/scene.h"

namespace raster {

// balboa's starter code renders part 2.1 at 640 x 480; the document's JSON scenes use the same resolution.
inline constexpr int kSeed001DefaultWidth = 640;
inline constexpr int kSeed001DefaultHeight = 480;
// balboa's projection has no far plane; raster's clipper needs one, so it sits far beyond any course scene.
inline constexpr float kSeed001Far = 1e9f;
inline constexpr float kSeed001DefaultS = 1.0f;
inline constexpr float kSeed001DefaultZNear = 1e-6f;
inline constexpr float kSeed001Background = 0.5f;  // the document's grey (0.5, 0.5, 0.5)

// Empty when s (half the height of the image plane at z = -1) and z_near are usable, else what is wrong.
std::string seed001_camera_problem(float s, float z_near);

// What every balboa render shares: the camera at the origin looking down -z with y up and the image plane z = -1
// spanning [-s*a, s*a] x [-s, s] (so a vertical field of view of 2 atan(s)), the near plane at distance z_near,
// 4x4 grid supersampling, unlit shading (face colours, else perspective-correct vertex colours) and no culling.
// Callers check seed001_camera_problem first.
void set_seed001_camera(float s, float z_near, Scene& scene);

// Part 2.1: one camera-space triangle in a constant colour on the grey background, 640 x 480.
struct Seed001Triangle {
    std::array<glm::vec3, 3> vertices{};
    glm::vec3 color{1.0f};
    float s = kSeed001DefaultS;
    float z_near = kSeed001DefaultZNear;
};
Scene seed001_triangle_scene(const Seed001Triangle& triangle);

}  // namespace raster
