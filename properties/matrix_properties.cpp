// Matrix properties on the float matrices the implementation's blocks and vertex stage build: the view matrix
// is rigid and puts the eye at the origin and the target on -z; the projection maps the near and far planes to the
// ends of the depth range and the frustum's edges to the image border; round trips through the inverses hold; the
// model matrix of a scale-rotate-translate chain is T R S; the normal matrix keeps normals perpendicular to
// surfaces. Each takes the building block under test from the implementation.
//
// Bounds use u = 2^-24 and are evaluated in double on the float matrices.
#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "properties/depth_precision.h"
#include "properties/failure.h"
#include "properties/generators.h"
#include "properties/generators/primitives.h"
#include "properties/printing.h"
#include "properties/property_registry.h"
#include "raster/transform/transform.h"
#include "raster/geometry/vertex_stage.h"
#include "raster/scene/scene.h"

namespace raster::properties {
namespace {


double norm1(const glm::dvec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }

// The largest entry of |a - b|.
double largest_difference(const glm::dmat4& a, const glm::dmat4& b) {
    double d = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) d = std::max(d, std::fabs(a[c][r] - b[c][r]));
    return d;
}

double largest_difference(const glm::dmat3& a, const glm::dmat3& b) {
    double d = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) d = std::max(d, std::fabs(a[c][r] - b[c][r]));
    return d;
}

// The orthonormality bound of a look-at basis: 2^-21 (1 + 1 / sin(angle between up and eye - target)).
double basis_error(const CameraCase& c) {
    const glm::dvec3 up(c.up), view = glm::dvec3(c.eye) - glm::dvec3(c.target);
    const double sine = glm::length(glm::cross(up, view)) / (glm::length(up) * glm::length(view));
    return std::ldexp(1.0 + 1.0 / sine, -21);
}

// A view-space point of the lens's frustum at view depth w, `across` its cross-section.
glm::vec3 frustum_point(const LensCase& c, float w) {
    const double half = std::tan(static_cast<double>(c.fov_y_degrees) * kPi / 360.0);
    return {static_cast<float>(c.across.x * w * half * c.aspect), static_cast<float>(c.across.y * w * half), -w};
}

double scale_ratio(const glm::vec3& s) {
    const glm::dvec3 a = glm::abs(glm::dvec3(s));
    return std::max({a.x, a.y, a.z}) / std::min({a.x, a.y, a.z});
}

glm::mat4 model_of(const ScaleRotateTranslate& chain) {
    return translate_matrix(chain.offset) * rotate_matrix(chain.degrees, chain.axis) * scale_matrix(chain.scale);
}

}  // namespace

// With theta the angle between up and eye - target: the basis w = normalize(eye - target),
// u = normalize(up x w), v = w x u carries |u.w| <= 2^-22 / sin(theta) (the cross product's rounding relative to
// its length |up| sin(theta)), v is orthogonal to both within 2^-22, and every length is 1 within 4u; so
// |R^T R - I| <= e = 2^-21 (1 + 1 / sin theta) entry by entry and |det R - 1| <= 3e. The eye maps within
// 2^-21 |eye|_1 of the origin (three-term float dot products against the double evaluation), and the target within
// e |target - eye| + 2^-22 (|eye| + |target|) + 2^-21 |eye|_1 of (0, 0, -|target - eye|) (float subtraction of
// eye and target turns the direction by 2^-23 (|eye| + |target|) / |target - eye|). Up maps into the upper half of
// the view's y-z plane.
RASTER_PROPERTY(ViewMatrix, isRigidAndMapsEyeToOriginAndTargetOntoNegativeZ) {
    const CameraCase c = *cameras();
    RC_CLASSIFY(true, c.kind);
    const glm::dmat4 view(impl.blocks.look_at(c.eye, c.target, c.up));
    const glm::dmat3 r(view);
    const double e = basis_error(c);
    const double off = largest_difference(glm::transpose(r) * r, glm::dmat3(1.0));
    if (!(off <= e)) fail_case("R^T R is " + double_literal(off) + " from I (bound " + double_literal(e) + ")");
    const double det = glm::determinant(r);
    if (!(std::fabs(det - 1.0) <= 3.0 * e)) fail_case("det R = " + double_literal(det));
    // Up stays up: it has no right component (u is up x w, normalised: within e |up|), and a non-negative y (its
    // y is |up| sin(theta) exactly; a view turned half a turn about -z, with u and v both reversed, passes the
    // checks above and the two below, but not this one).
    const glm::dvec3 up_view = r * glm::dvec3(c.up);
    const double up_bound = e * glm::length(glm::dvec3(c.up));
    if (!(std::fabs(up_view.x) <= up_bound && up_view.y >= -up_bound))
        fail_case("up maps to (" + double_literal(up_view.x) + ", " + double_literal(up_view.y) + ", " +
                  double_literal(up_view.z) + "), not into the upper half of the view's y-z plane");
    const glm::dvec3 eye(c.eye), target(c.target);
    const glm::dvec3 eye_view(view * glm::dvec4(eye, 1.0));
    const double eye_bound = std::ldexp(norm1(eye), -21);
    if (!(std::max({std::fabs(eye_view.x), std::fabs(eye_view.y), std::fabs(eye_view.z)}) <= eye_bound))
        fail_case("the eye maps to (" + double_literal(eye_view.x) + ", " + double_literal(eye_view.y) + ", " +
                  double_literal(eye_view.z) + "), not the origin (bound " + double_literal(eye_bound) + ")");
    const double distance = glm::length(target - eye);
    const glm::dvec3 target_view(view * glm::dvec4(target, 1.0));
    const glm::dvec3 miss = glm::abs(target_view - glm::dvec3(0.0, 0.0, -distance));
    const double target_bound = e * distance + std::ldexp(glm::length(eye) + glm::length(target), -22) + eye_bound;
    if (!(std::max({miss.x, miss.y, miss.z}) <= target_bound))
        fail_case("the target maps to (" + double_literal(target_view.x) + ", " + double_literal(target_view.y) + ", " +
                  double_literal(target_view.z) + "), not (0, 0, " + double_literal(-distance) + ")");
}

// Points anywhere on the near plane get depth 1 and on the far plane depth 0, within depth_error_at_near and
// depth_error_at_far (depth_precision.h), and w equal to their view depth exactly.
RASTER_PROPERTY(Projection, mapsNearAndFarPlanesToTheEndsOfTheDepthRange) {
    const LensCase c = *lenses();
    RC_CLASSIFY(true, c.kind);
    const glm::mat4 projection = impl.blocks.perspective(c.fov_y_degrees, c.aspect, c.near, c.far);
    auto check_plane = [&](float w, double expected, double bound, const char* name) {
        const glm::vec4 clip = projection * glm::vec4(frustum_point(c, w), 1.0f);
        if (clip.w != w) fail_case(std::string("w on the ") + name + " plane is " + float_literal(clip.w) + ", not " + float_literal(w));
        const double d = static_cast<double>(clip.z) / static_cast<double>(clip.w);
        if (!(std::fabs(d - expected) <= bound))
            fail_case(std::string("the ") + name + " plane gets depth " + double_literal(d) + ", not " + double_literal(expected) +
                      " within " + double_literal(bound));
    };
    check_plane(c.near, 1.0, depth_error_at_near(c.near, c.far), "near");
    check_plane(c.far, 0.0, depth_error_at_far(c.near, c.far), "far");
}

// An orthographic projection (docs/conventions.md) maps a view point (x, y, -t) to x / (height aspect / 2),
// y / (height / 2) and reversed-Z depth (far - t) / (far - near), with w exactly 1, for any lens (the lenses'
// near and far, near 0 too; heights from 1e-3 to 1e4) and any point of the box. Each entry is built in double from
// floats and rounded (with the aspect's own rounding: 3u), and the product and sum add 2: so x and y are within
// 5u of exact, relatively, and z within 5u of (t + far) / (far - near), the magnitudes of its two terms.
RASTER_PROPERTY(Projection, orthographicMapsItsBoxToTheClipCubeWithWOne) {
    const LensCase c = *lenses();
    const float height = static_cast<float>(log_uniform(1e-3, 1e4));
    const float near = coin() ? 0.0f : c.near;
    RC_CLASSIFY(near == 0.0f, "near 0");
    const glm::mat4 projection = impl.blocks.orthographic(height, c.aspect, near, c.far);
    const double half_height = 0.5 * double(height), half_width = half_height * double(c.aspect);
    const double t = double(near) + unit() * (double(c.far) - double(near));
    const glm::dvec3 view(signed_unit() * half_width, signed_unit() * half_height, -t);
    const glm::vec4 clip = projection * glm::vec4(glm::vec3(view), 1.0f);
    if (clip.w != 1.0f) fail_case("w is " + float_literal(clip.w) + ", not 1");
    const glm::dvec3 exact(double(float(view.x)) / half_width, double(float(view.y)) / half_height,
                           (double(c.far) - double(float(view.z) * -1.0f)) / (double(c.far) - double(near)));
    const double u = std::ldexp(1.0, -24);
    const glm::dvec3 bound(5.0 * u * std::fabs(exact.x), 5.0 * u * std::fabs(exact.y),
                           5.0 * u * (-double(float(view.z)) + double(c.far)) / (double(c.far) - double(near)));
    const glm::dvec3 miss = glm::abs(glm::dvec3(clip) - exact);
    if (!(miss.x <= bound.x && miss.y <= bound.y && miss.z <= bound.z))
        fail_case("(" + double_literal(view.x) + ", " + double_literal(view.y) + ", " + double_literal(view.z) +
                  ") maps to (" + float_literal(clip.x) + ", " + float_literal(clip.y) + ", " + float_literal(clip.z) +
                  "), not (" + double_literal(exact.x) + ", " + double_literal(exact.y) + ", " + double_literal(exact.z) +
                  ") within (" + double_literal(bound.x) + ", " + double_literal(bound.y) + ", " + double_literal(bound.z) + ")");
}

// Through the implementation's vertex stage, for any image size: points on the frustum's edges at any depth land
// on NDC x = +-1 and y = +-1 within 2^-21 (the vertex's rounding, the float aspect W / H, the entry
// focal / aspect rounded to float, and the product: five roundings of u, well under 8u).
RASTER_PROPERTY(Projection, mapsTheFrustumEdgesToTheImageBorder) {
    const LensCase c = *lenses();
    RC_CLASSIFY(true, c.kind);
    Scene scene;
    scene.settings.width = c.width;
    scene.settings.height = c.height;
    scene.settings.shading = ShadingMode::unlit;
    scene.camera.eye = glm::vec3(0.0f);
    scene.camera.target = {0.0f, 0.0f, -1.0f};
    scene.camera.up = {0.0f, 1.0f, 0.0f};
    scene.camera.fov_y_degrees = c.fov_y_degrees;
    scene.camera.near = c.near;
    scene.camera.far = c.far;
    const double half = std::tan(static_cast<double>(c.fov_y_degrees) * kPi / 360.0);
    const double aspect = static_cast<double>(c.width) / c.height, t = c.depth;
    SceneMesh mesh;
    const double corners[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    for (const auto& k : corners)
        mutable_data(mesh).positions.push_back({static_cast<float>(k[0] * t * half * aspect), static_cast<float>(k[1] * t * half),
                                       static_cast<float>(-t)});
    mutable_data(mesh).triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
    scene.meshes.push_back(mesh);
    const TransformedScene out = impl.stages.vertex(scene, vertex_stage_needs(ShadingMode::unlit));
    const double bound = std::ldexp(1.0, -21);
    for (size_t i = 0; i < 4; ++i) {
        const glm::dvec4 p(out.clip.at(i));
        const double x = p.x / p.w, y = p.y / p.w;
        if (!(std::fabs(x - corners[i][0]) <= bound && std::fabs(y - corners[i][1]) <= bound))
            fail_case("the frustum corner (" + std::to_string(int(corners[i][0])) + ", " + std::to_string(int(corners[i][1])) +
                      ") of a " + std::to_string(c.width) + "x" + std::to_string(c.height) + " image lands at NDC (" +
                      double_literal(x) + ", " + double_literal(y) + ")");
    }
}

// view * look_at_inverse = I within the view bounds above; projecting then unprojecting (double inverse of the
// float matrix) returns a view-space point within 2^-21 of its largest coordinate (x and y carry one rounding;
// z and w pass through the depth row, whose rounding is below 5u relative after the homogeneous divide); the
// viewport and its inverse return NDC within 2^-21; and normal_matrix(M)^T M = I within 2^-20 kappa, kappa the
// ratio of M's largest to smallest scale factor (each cofactor of R S is rounded relative to its column's scale).
RASTER_PROPERTY(Matrices, roundTripsThroughTheInversesHold) {
    const CameraCase camera = *cameras();
    const LensCase lens = *lenses();
    const ModelCase model = *models();
    RC_CLASSIFY(true, camera.kind);

    // View and its inverse (the look-at model matrix).
    const glm::dmat4 there_and_back = glm::dmat4(impl.blocks.look_at(camera.eye, camera.target, camera.up)) *
                                      glm::dmat4(impl.blocks.look_at_inverse(camera.eye, camera.target, camera.up));
    const double e = basis_error(camera);
    const double rotation_off = largest_difference(glm::dmat3(there_and_back), glm::dmat3(1.0));
    const glm::dvec3 translation(there_and_back[3]);
    const double translation_bound = std::ldexp(norm1(glm::dvec3(camera.eye)), -21);
    if (!(rotation_off <= e) ||
        !(std::max({std::fabs(translation.x), std::fabs(translation.y), std::fabs(translation.z)}) <= translation_bound))
        fail_case("view * inverse view is not I: rotation off by " + double_literal(rotation_off) + ", translation (" +
                  double_literal(translation.x) + ", " + double_literal(translation.y) + ", " + double_literal(translation.z) + ")");

    // Projection and its inverse on a point of the frustum.
    const glm::mat4 projection = impl.blocks.perspective(lens.fov_y_degrees, lens.aspect, lens.near, lens.far);
    const glm::vec3 point = frustum_point(lens, lens.depth);
    glm::dvec4 back = glm::inverse(glm::dmat4(projection)) * glm::dvec4(projection * glm::vec4(point, 1.0f));
    back /= back.w;
    const glm::dvec3 miss = glm::abs(glm::dvec3(back) - glm::dvec3(point));
    const double size = std::max({std::fabs(point.x), std::fabs(point.y), std::fabs(point.z)});
    if (!(std::max({miss.x, miss.y, miss.z}) <= std::ldexp(size, -21)))
        fail_case("unprojecting the projected point " + literal(point) + " gives (" + double_literal(back.x) + ", " +
                  double_literal(back.y) + ", " + double_literal(back.z) + ")");

    // Viewport: the documented corners, and the inverse.
    const glm::mat4 viewport = impl.blocks.viewport(lens.width, lens.height);
    const glm::vec4 top_left = viewport * glm::vec4(-1.0f, 1.0f, 0.0f, 1.0f);
    const glm::vec4 bottom_right = viewport * glm::vec4(1.0f, -1.0f, 0.0f, 1.0f);
    if (top_left.x != 0.0f || top_left.y != 0.0f || bottom_right.x != float(lens.width) || bottom_right.y != float(lens.height))
        fail_case("the viewport does not map NDC (-1, 1) to (0, 0) and (1, -1) to (width, height)");
    const glm::dvec4 ndc(lens.across.x, lens.across.y, 0.5, 1.0);
    const glm::dvec4 ndc_back = glm::inverse(glm::dmat4(viewport)) * glm::dvec4(viewport * glm::vec4(ndc));
    if (!(std::fabs(ndc_back.x - ndc.x) <= std::ldexp(1.0, -21) && std::fabs(ndc_back.y - ndc.y) <= std::ldexp(1.0, -21)))
        fail_case("the viewport round trip moves NDC (" + double_literal(ndc.x) + ", " + double_literal(ndc.y) + ")");

    // Normal matrix: N^T M = (M^-1 M) = I for the model's 3x3.
    const glm::mat4 m = model_of(model.chain);
    const glm::dmat3 product = glm::transpose(glm::dmat3(impl.blocks.normal_matrix(m))) * glm::dmat3(glm::mat3(m));
    const double normal_bound = std::ldexp(scale_ratio(model.chain.scale), -20);
    const double normal_off = largest_difference(product, glm::dmat3(1.0));
    if (!(normal_off <= normal_bound))
        fail_case("normal_matrix(M)^T M is " + double_literal(normal_off) + " from I (bound " + double_literal(normal_bound) + ")");
}

// The loader's matrix for a chain "scale, rotate, translate" is translate * rotate * scale: every 3x3 entry is one
// float product R_ij s_j (within u max|s|), the translation column is t exactly, the last row (0, 0, 0, 1); the
// bound is 2^-22 (max|s| + |t|).
RASTER_PROPERTY(ModelMatrix, isTranslateTimesRotateTimesScale) {
    const ModelCase c = *models();
    RC_CLASSIFY(true, c.kind);
    const glm::dmat4 built(impl.blocks.model_matrix(c.chain));
    const glm::dmat4 expected = glm::dmat4(translate_matrix(c.chain.offset)) *
                                glm::dmat4(rotate_matrix(c.chain.degrees, c.chain.axis)) *
                                glm::dmat4(scale_matrix(c.chain.scale));
    const glm::dvec3 s = glm::abs(glm::dvec3(c.chain.scale)), t = glm::abs(glm::dvec3(c.chain.offset));
    const double bound = std::ldexp(std::max({s.x, s.y, s.z}) + std::max({t.x, t.y, t.z}), -22);
    const double off = largest_difference(built, expected);
    if (!(off <= bound) || built[0][3] != 0.0 || built[1][3] != 0.0 || built[2][3] != 0.0 || built[3][3] != 1.0)
        fail_case("the model matrix differs from T R S by " + double_literal(off) + " (bound " + double_literal(bound) + ")");
}

// A triangle with its face normal as vertex normals, through the implementation's vertex stage with a model
// T R S (mirrors, non-uniform scales up to 1e6 apart): each world normal is perpendicular to the world triangle's
// edges within 2^-20 (1 + kappa + 4 (max|s| max|p| + |t|) / |M e|) in cosine (the object normal's float rounding,
// the inverse-transpose's relative error kappa 2^-22, and the world positions' float rounding against the edge's
// length). The normal-matrix block alone, against edges transformed in double, within 2^-20 (1 + kappa).
RASTER_PROPERTY(NormalMatrix, keepsNormalsPerpendicularToSurfaces) {
    const ModelCase c = *models();
    RC_CLASSIFY(true, c.kind);
    const glm::mat4 m = model_of(c.chain);
    const glm::dvec3 p0(c.triangle[0]), p1(c.triangle[1]), p2(c.triangle[2]);
    const glm::vec3 normal(glm::normalize(glm::cross(p1 - p0, p2 - p0)));
    const double kappa = scale_ratio(c.chain.scale);

    Scene scene;
    scene.settings.shading = ShadingMode::blinn_phong;
    SceneMesh mesh;
    mutable_data(mesh).positions = {c.triangle[0], c.triangle[1], c.triangle[2]};
    mutable_data(mesh).normals = {normal, normal, normal};
    mutable_data(mesh).triangles = {{{0, 1, 2}}};
    mesh.transform.steps = {MatrixStep{m}};
    scene.meshes.push_back(mesh);
    const TransformedScene out = impl.stages.vertex(scene, vertex_stage_needs(ShadingMode::blinn_phong));
    const glm::dvec3 s = glm::abs(glm::dvec3(c.chain.scale)), t = glm::abs(glm::dvec3(c.chain.offset));
    const double reach = std::max({s.x, s.y, s.z}) * std::max({glm::length(p0), glm::length(p1), glm::length(p2)}) +
                         std::max({t.x, t.y, t.z});
    const glm::dmat3 n_block(impl.blocks.normal_matrix(m));
    for (size_t j = 1; j < 3; ++j) {
        // Through the vertex stage.
        const glm::dvec3 n(out.world_normal.at(j)), edge = glm::dvec3(out.world_position.at(j)) - glm::dvec3(out.world_position.at(0));
        const double cosine = std::fabs(glm::dot(n, edge)) / (glm::length(n) * glm::length(edge));
        const double bound = std::ldexp(1.0 + kappa + 4.0 * reach / glm::length(edge), -20);
        if (!(cosine <= bound))
            fail_case("the vertex stage's world normal makes cos " + double_literal(cosine) + " with a world edge (bound " +
                      double_literal(bound) + ")");
        // The normal-matrix block alone, against the edge transformed in double.
        const glm::dvec3 nb = n_block * glm::dvec3(normal);
        const glm::dvec3 eb = glm::dmat3(glm::mat3(m)) * (glm::dvec3(c.triangle[j]) - p0);
        const double cosine_block = std::fabs(glm::dot(nb, eb)) / (glm::length(nb) * glm::length(eb));
        if (!(cosine_block <= std::ldexp(1.0 + kappa, -20)))
            fail_case("normal_matrix(M) n makes cos " + double_literal(cosine_block) + " with M e");
    }
}

}  // namespace raster::properties
