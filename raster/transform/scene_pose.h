// An animated scene posed at an instant: each moved mesh's transform chain, each carried light's position and the
// carried camera, from the scene's animation (raster/scene/animation.h) at that time.
#pragma once

#include <glm/mat4x4.hpp>

#include "raster/scene/scene.h"

namespace raster {

// Poses `scene` at `time` seconds; does nothing to a scene without animation.
void pose_scene(Scene& scene, float time);

// A camera at the pose's origin looking down its -z with its +y up (glTF's convention), field and planes unchanged.
void camera_from_pose(const glm::mat4& pose, Camera& camera);

}  // namespace raster
