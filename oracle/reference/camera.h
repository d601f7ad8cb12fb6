// The oracle's camera, written from the documented conventions (docs/conventions.md) in double: the view basis, the projection (focal
// length, aspect, reversed-Z depth), the viewport mapping and the camera ray through a screen point. It shares
// nothing with raster's transform code but the scene's Camera.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "raster/scene/scene.h"

namespace raster::oracle {

struct OracleCamera {
    glm::dvec3 eye{0.0};
    // The view basis in world space: right (view x), up (view y), back (view z; the camera looks down -back).
    // back = normalize(eye - target), right = normalize(cross(up, back)), up = cross(back, right).
    glm::dvec3 right{1.0, 0.0, 0.0}, up{0.0, 1.0, 0.0}, back{0.0, 0.0, 1.0};
    bool orthographic = false;  // parallel rays along -back (docs/conventions.md "Orthographic cameras")
    double focal = 1.0;   // perspective: 1 / tan(fov_y / 2)
    double half_height = 1.0;  // orthographic: half the view volume's height (its half width: half_height aspect)
    double aspect = 1.0;  // width / height
    double near = 0.1, far = 100.0;
    int width = 1, height = 1;
    glm::dmat4 view{1.0};        // world -> view: rows right, up, back; the eye goes to the origin
    // view -> clip: perspective (focal/aspect x, focal y, reversed-Z z, w = -z_view); orthographic
    // (x / (half_height aspect), y / half_height, (far + z_view) / (far - near), w = 1).
    glm::dmat4 projection{0.0};
};

OracleCamera oracle_camera(const Camera& camera, int width, int height);

// A world point in view space.
glm::dvec3 view_of_world(const OracleCamera& camera, const glm::dvec3& world);

// Screen space (pixels, y down, pixel (x, y) covering [x, x+1) x [y, y+1)) and NDC: NDC (-1, +1) is the screen's
// upper-left corner (0, 0), NDC (+1, -1) its lower-right (width, height).
glm::dvec2 ndc_of_screen(const OracleCamera& camera, const glm::dvec2& screen);
glm::dvec2 screen_of_ndc(const OracleCamera& camera, const glm::dvec2& ndc);

// The view-space ray through a screen point: from its origin (the eye, the view-space origin, for a perspective
// camera; the point of the plane z = 0 under the screen point for an orthographic one) along a direction with
// z = -1, so that the ray parameter is the view depth and the near and far planes are t = near and t = far.
glm::dvec3 ray_origin(const OracleCamera& camera, const glm::dvec2& screen);
glm::dvec3 ray_direction(const OracleCamera& camera, const glm::dvec2& screen);

// Whether a view-space triangle is front-facing (docs/conventions.md "Front faces": counter-clockwise in NDC): its
// normal points back at the eye at the view-space origin, dot(normal, a) < 0 (perspective keeps the orientation
// of what lies in front of the eye); orthographic, it points along view +z, towards the plane through the eye.
bool faces_viewer(const OracleCamera& camera, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// Reversed-Z depth d = z_clip / w_clip at view depth t (> 0 for a perspective camera): 1 at near, 0 at far.
double reversed_z(const OracleCamera& camera, double view_depth);
// |d(reversed_z)/dt| bounded over [t - error, t + error]: how far an error in t can move d.
double reversed_z_error_of_view_depth(const OracleCamera& camera, double view_depth, double error);

}  // namespace raster::oracle
