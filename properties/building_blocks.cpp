// The real transform chain, observed the way users reach it: through a scene file and the loader.
#include "properties/building_blocks.h"

#include <cstdio>
#include <string>

#include "raster/compat/scene_loader.h"
#include "raster/transform/model_matrix.h"

namespace raster::properties {

std::string yaml_number(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
    return text;
}

std::string yaml_vector(const glm::vec3& v) {
    char text[128];  // formatted in one go: g++ 12 warns falsely (-Wrestrict) on "literal" + std::string&&
    std::snprintf(text, sizeof text, "[%.9g, %.9g, %.9g]", static_cast<double>(v.x), static_cast<double>(v.y),
                  static_cast<double>(v.z));
    return text;
}

std::string scene_file_with_chain(const ScaleRotateTranslate& chain, const std::array<glm::vec3, 3>& triangle,
                                  const std::string& preamble) {
    return preamble +
           "meshes:\n"
           "  - vertices: [" + yaml_vector(triangle[0]) + ", " + yaml_vector(triangle[1]) + ", " + yaml_vector(triangle[2]) + "]\n"
           "    faces: [[0, 1, 2]]\n"
           "    transform:\n"
           "      - scale: " + yaml_vector(chain.scale) + "\n"
           "      - rotate: {angle: " + yaml_number(chain.degrees) + ", axis: " + yaml_vector(chain.axis) + "}\n"
           "      - translate: " + yaml_vector(chain.offset) + "\n";
}

glm::mat4 model_matrix_from_scene_file(const ScaleRotateTranslate& chain) {
    const std::string text = scene_file_with_chain(chain, {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)});
    return model_matrix(parse_scene(text, "model_matrix_from_scene_file.yaml").meshes.at(0).transform);
}

}  // namespace raster::properties
