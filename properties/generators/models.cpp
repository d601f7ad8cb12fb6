// The model generator: scale-rotate-translate chains with a triangle in object space.
#include "properties/generators/models.h"

#include <glm/geometric.hpp>

#include "properties/generators/primitives.h"
#include "properties/printing.h"

namespace raster::properties {

std::ostream& operator<<(std::ostream& os, const ModelCase& c) {
    return os << "ModelCase{\"" << c.kind << "\", {" << literal(c.chain.scale) << ", " << float_literal(c.chain.degrees)
              << ", " << literal(c.chain.axis) << ", " << literal(c.chain.offset) << "}, {" << literal(c.triangle[0])
              << ", " << literal(c.triangle[1]) << ", " << literal(c.triangle[2]) << "}}";
}

Gen<ModelCase> models() {
    return gen::exec([] {
        ModelCase c;
        const int kind = *gen::weightedElement<int>({{3, 0}, {1, 1}, {1, 2}});
        for (int i = 0; i < 3; ++i) {
            const double magnitude = kind == 1 ? log_uniform(1e-3, 1e3) : log_uniform(0.1, 10.0);
            c.chain.scale[i] = static_cast<float>((coin() ? 1 : -1) * magnitude);
        }
        if (kind == 2) c.chain.scale = glm::vec3(c.chain.scale.x);
        c.kind = kind == 0 ? "scales 0.1 to 10" : kind == 1 ? "scales 1e-3 to 1e3" : "uniform scale";
        c.chain.degrees = static_cast<float>(720 * unit() - 360);
        c.chain.axis = *gen::suchThat(gen::exec([] { return random_vector(1); }),
                                      [](const glm::vec3& a) { return glm::dot(a, a) > 1e-2f; });
        const int where = *gen::weightedElement<int>({{3, 0}, {1, 1}, {1, 2}});
        c.chain.offset = where == 0 ? random_vector(100) : where == 1 ? random_vector(1e4) : glm::vec3(0.0f);
        if (where == 1) c.kind += ", far away";
        c.triangle = *gen::suchThat(gen::exec([] { return std::array<glm::vec3, 3>{random_vector(1), random_vector(1), random_vector(1)}; }),
                                    [](const std::array<glm::vec3, 3>& t) {
                                        const glm::vec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
                                        return glm::dot(n, n) > 0.01f;
                                    });
        return c;
    });
}

}  // namespace raster::properties
