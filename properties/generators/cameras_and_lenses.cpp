// The camera and lens generators for the matrix and depth properties: random, far, close, nearly degenerate
// cameras, and lenses from typical to near = 1e-6, far = 1e9.
#include "properties/generators/cameras_and_lenses.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "properties/generators/primitives.h"
#include "properties/printing.h"
#include "raster/scene/validation.h"

namespace raster::properties {

std::ostream& operator<<(std::ostream& os, const CameraCase& c) {
    return os << "CameraCase{\"" << c.kind << "\", " << literal(c.eye) << ", " << literal(c.target) << ", "
              << literal(c.up) << "}";
}

std::ostream& operator<<(std::ostream& os, const LensCase& c) {
    return os << "LensCase{\"" << c.kind << "\", " << float_literal(c.fov_y_degrees) << ", " << float_literal(c.aspect)
              << ", " << float_literal(c.near) << ", " << float_literal(c.far) << ", " << c.width << ", " << c.height
              << ", " << float_literal(c.depth) << ", " << float_literal(c.farther) << ", glm::vec2("
              << float_literal(c.across.x) << ", " << float_literal(c.across.y) << ")}";
}

Gen<CameraCase> cameras() {
    auto valid = [](const CameraCase& c) {
        Camera camera;
        camera.eye = c.eye;
        camera.target = c.target;
        camera.up = c.up;
        return !camera_problem(camera);
    };
    return gen::suchThat(
        gen::weightedOneOf<CameraCase>({
            {4, gen::exec([] { return CameraCase{"random", random_vector(100), random_vector(100), random_vector(1)}; })},
            {1, gen::exec([] {
                 const glm::vec3 eye = random_vector(1e5);
                 return CameraCase{"far from the origin", eye, eye + random_vector(100), random_vector(1)};
             })},
            {1, gen::exec([] {
                 const glm::vec3 eye = random_vector(10);
                 return CameraCase{"target 1e-3 away", eye, eye + 1e-3f * random_direction(), random_vector(1)};
             })},
            {1, gen::exec([] {
                 const glm::vec3 eye = random_vector(10), direction = random_direction();
                 // Up within 1e-3 to 1e-2 radians of the view direction.
                 glm::vec3 side = glm::cross(direction, random_direction());
                 side /= std::sqrt(glm::dot(side, side));
                 const float angle = static_cast<float>(log_uniform(1e-3, 1e-2));
                 return CameraCase{"up nearly parallel", eye, eye + 5.0f * direction,
                                   (coin() ? 1.0f : -1.0f) * direction + angle * side};
             })},
            {1, gen::exec([] {
                 return CameraCase{"up 1e-3 or 1e3 long", random_vector(10), random_vector(10),
                                   (coin() ? 1e-3f : 1e3f) * random_direction()};
             })},
            {1, gen::exec([] {
                 const int axis = *uniform(0, 2);
                 glm::vec3 direction(0.0f), up(0.0f);
                 direction[axis] = coin() ? 1.0f : -1.0f;
                 up[(axis + 1) % 3] = 1.0f;
                 const glm::vec3 eye = glm::round(random_vector(10));
                 return CameraCase{"along an axis", eye, eye + 3.0f * direction, up};
             })},
        }),
        valid);
}

Gen<LensCase> lenses() {
    return gen::exec([] {
        LensCase c;
        std::string kind;
        c.fov_y_degrees = *gen::weightedOneOf<float>({{4, gen::exec([] { return static_cast<float>(10 + 110 * unit()); })},
                                                      {1, gen::just(1.0f)},
                                                      {1, gen::just(179.0f)}});
        if (c.fov_y_degrees == 1.0f || c.fov_y_degrees == 179.0f) kind += "fov " + float_literal(c.fov_y_degrees) + ", ";
        c.width = *uniform(1, 4096);
        c.height = *uniform(1, 4096);
        c.aspect = static_cast<float>(c.width) / static_cast<float>(c.height);
        const int range = *gen::weightedElement<int>({{3, 0}, {1, 1}, {1, 2}});
        if (range == 0) {
            c.near = static_cast<float>(log_uniform(1e-3, 1.0));
            c.far = static_cast<float>(c.near * log_uniform(10.0, 1e5));
            kind += "typical near and far";
        } else if (range == 1) {
            c.near = 1e-6f;
            c.far = 1e9f;
            kind += "near 1e-6, far 1e9";
        } else {
            c.near = static_cast<float>(log_uniform(1e-3, 10.0));
            c.far = c.near * (1.0f + std::ldexp(1.0f, -10));
            kind += "far = near (1 + 2^-10)";
        }
        // Two view depths in [near, far], the second at least 2^-19 relatively farther (see the depth properties).
        const double gap = std::ldexp(1.0, -19);
        const double top = double(c.far) / (1.0 + gap);
        c.depth = static_cast<float>(*gen::weightedOneOf<double>({{4, gen::exec([near = c.near, top] { return log_uniform(near, top); })},
                                                                 {1, gen::just(double(c.near))}}));
        const double ratio = log_uniform(1.0 + 2 * gap, std::max(1.0 + 2 * gap, double(c.far) / c.depth));
        c.farther = static_cast<float>(std::min<double>(c.far, c.depth * ratio));
        if (c.farther <= c.depth * (1.0 + gap)) c.farther = c.far;
        c.across = {static_cast<float>(signed_unit()), static_cast<float>(signed_unit())};
        c.kind = kind;
        return c;
    });
}

}  // namespace raster::properties
