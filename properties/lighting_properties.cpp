// The lighting property: a light marked as attenuating falls off with the inverse square of its distance, checked
// through the implementation's lighting function.
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "properties/failure.h"
#include "properties/generators.h"
#include "properties/printing.h"
#include "properties/property_registry.h"

namespace raster::properties {

// Diffuse-only material, one light along a direction in front of the surface: the attenuated diffuse term over the
// unattenuated one is 1 / |L - P|^2 (in double, from the float positions) within 2^-20 relative. Both terms share
// every operation but the division by the float squared distance: the difference's rounding (2u), the dot product
// (3u), the division (u) and the two products after it in each term (4u) add up to 10u < 2^-20, u = 2^-24.
RASTER_PROPERTY(Lighting, attenuatedLightFallsOffWithTheInverseSquareOfDistance) {
    const LightCase c = *lights();
    RC_CLASSIFY(true, c.kind);
    const glm::vec3 point(0.25f, -0.5f, 0.125f);
    Material material;
    material.ambient = glm::vec3(0.0f);
    material.diffuse = glm::vec3(1.0f);
    material.specular = glm::vec3(0.0f);
    Light light;
    light.position = point + c.distance * c.direction;
    light.color = c.color;
    auto diffuse = [&](bool attenuate) {
        light.attenuate = attenuate;
        return impl.stages.lighting(point, c.normal, c.normal, material, {light}, glm::vec3(0.0f), SpecularModel::blinn, nullptr).diffuse;
    };
    const glm::dvec3 attenuated(diffuse(true)), plain(diffuse(false));
    const glm::dvec3 offset = glm::dvec3(light.position) - glm::dvec3(point);
    const double expected = 1.0 / glm::dot(offset, offset);
    for (int k = 0; k < 3; ++k) {
        const double ratio = attenuated[k] / plain[k];
        if (!(std::fabs(ratio / expected - 1.0) <= std::ldexp(1.0, -20)))
            fail_case("attenuated / unattenuated = " + double_literal(ratio) + " for a light " + double_literal(std::sqrt(1.0 / expected)) +
                      " away, not 1 / r^2 = " + double_literal(expected));
    }
}

}  // namespace raster::properties
