// The lighting stage's faulty variant of the bug catalogue, with the signature of PipelineStages::lighting;
// lighting_faults.cpp describes the bug where it is written.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "raster/pipeline/shade.h"
#include "raster/scene/scene.h"

namespace raster::mutants {

// "1/r^2 attenuation missing"
LightingTerms lighting_without_attenuation(const glm::vec3& position, const glm::vec3& normal, const glm::vec3& to_eye,
                                           const Material& material, const std::vector<Light>& lights,
                                           const glm::vec3& ambient_light, SpecularModel model);

}  // namespace raster::mutants
