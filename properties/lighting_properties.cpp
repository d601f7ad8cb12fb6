// The lighting property, through the implementation's lighting function.
#include "properties/lighting_properties.h"

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "properties/failure.h"
#include "properties/generators.h"
#include "properties/printing.h"

namespace raster::properties {

void check_an_attenuated_light_falls_off_with_the_inverse_square_of_distance(const Implementation& impl) {
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
        return impl.stages.lighting(point, c.normal, c.normal, material, {light}, glm::vec3(0.0f), SpecularModel::blinn).diffuse;
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
