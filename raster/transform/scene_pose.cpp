// An animated scene posed at an instant (scene_pose.h).
#include "raster/transform/scene_pose.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "raster/scene/animation.h"
#include "raster/transform/model_matrix.h"

namespace raster {

void camera_from_pose(const glm::mat4& pose, Camera& camera) {
    camera.eye = glm::vec3(pose[3]);
    const glm::vec3 forward = glm::normalize(-glm::vec3(pose[2]));
    camera.target = camera.eye + forward * std::max(1.0f, glm::length(camera.eye));
    camera.up = glm::vec3(pose[1]);
}

void pose_scene(Scene& scene, float time) {
    if (!scene.animation) return;
    const SceneAnimation& animation = *scene.animation;
    scene.posed_at = time;
    for (size_t m = 0; m < scene.meshes.size() && m < animation.meshes.size(); ++m) {
        const SceneAnimation::Placement& placement = animation.meshes[m];
        if (placement.node < 0) continue;
        std::vector<TransformStep> steps = placement.local;
        const std::vector<TransformStep> chain = node_chain_at(animation, placement.node, time);
        steps.insert(steps.end(), chain.begin(), chain.end());
        scene.meshes[m].transform.steps = std::move(steps);
    }
    for (size_t l = 0; l < scene.lights.size() && l < animation.light_nodes.size(); ++l) {
        if (animation.light_nodes[l] < 0) continue;
        // At its node's origin, shining down its node's -z.
        const glm::mat4 pose = compose_steps(node_chain_at(animation, animation.light_nodes[l], time));
        scene.lights[l].position = glm::vec3(pose[3]);
        scene.lights[l].direction = -glm::vec3(pose[2]);
    }
    if (animation.camera_node >= 0)
        camera_from_pose(compose_steps(node_chain_at(animation, animation.camera_node, time)), scene.camera);
}

}  // namespace raster
