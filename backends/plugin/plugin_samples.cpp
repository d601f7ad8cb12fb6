// Checking and completing a plugin's per-sample answer (plugin_samples.h).
#include "backends/plugin/plugin_samples.h"

#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>

namespace raster::plugin {

glm::dvec3 solve_barycentrics(const std::array<glm::vec4, 3>& triangle, glm::dvec2 screen, int width, int height) {
    // The sample's NDC point P: the weights l with sum_i l_i (x_i, y_i) = P sum_i l_i w_i are the null vector of
    // the rows (x_i - P.x w_i) and (y_i - P.y w_i), their cross product.
    const glm::dvec2 ndc(2.0 * screen.x / width - 1.0, 1.0 - 2.0 * screen.y / height);
    glm::dvec3 along_x, along_y;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec4 v(triangle[static_cast<size_t>(i)]);
        along_x[i] = v.x - ndc.x * v.w;
        along_y[i] = v.y - ndc.y * v.w;
    }
    const glm::dvec3 weights = glm::cross(along_x, along_y);
    const double sum = weights.x + weights.y + weights.z;
    if (sum == 0.0 || !std::isfinite(sum)) return glm::dvec3(1.0 / 3.0);
    return weights / sum;
}

double vertex_view_depth(const glm::vec4& clip, const ClipSpaceFrame& frame) {
    if (!frame.orthographic) return clip.w;
    const double z = static_cast<double>(clip.z) / clip.w;
    return frame.far_plane - z * (static_cast<double>(frame.far_plane) - frame.near_plane);
}

namespace {

// How far from 1 the sum of a plugin's barycentrics may be before it breaks the contract: a gross error (weights of
// another triangle, or unnormalised ones); finer ones are for the oracle and the properties to judge.
constexpr double kBarycentricSumSlack = 0.01;

std::string where(const ClipSpaceFrame& frame, size_t index) {
    const size_t samples = frame.sample_offsets.size();
    const size_t pixel = index / samples;
    std::ostringstream text;
    text << "sample " << index % samples << " of pixel (" << pixel % static_cast<size_t>(frame.width) << ", "
         << pixel / static_cast<size_t>(frame.width) << ")";
    return text.str();
}

}  // namespace

void complete_samples(const ClipSpaceFrame& frame, bool barycentrics_written, const std::string& plugin,
                      VisibilityBuffer& samples) {
    const size_t count = frame.triangles.size();
    const size_t per_pixel = frame.sample_offsets.size();
    for (size_t i = 0; i < samples.size(); ++i) {
        const uint32_t id = samples.triangle[i];
        if (id == kNoTriangle) {
            samples.bary[i] = glm::vec3(0.0f);
            samples.view_depth[i] = 0.0f;
            continue;
        }
        if (id >= count)
            throw PluginError("plugin " + plugin + " wrote triangle " + std::to_string(id) + " at " + where(frame, i) +
                              ", but the frame has " + std::to_string(count) + " triangles");
        const std::array<glm::vec4, 3>& triangle = frame.triangles[id];
        glm::dvec3 bary;
        if (barycentrics_written) {
            bary = glm::dvec3(samples.bary[i]);
            const double sum = bary.x + bary.y + bary.z;
            if (!std::isfinite(sum) || std::abs(sum - 1.0) > kBarycentricSumSlack) {
                std::ostringstream text;
                text << "plugin " << plugin << " wrote barycentrics (" << bary.x << ", " << bary.y << ", " << bary.z
                     << ") for triangle " << id << " at " << where(frame, i)
                     << ": they must be finite and sum to 1 (within " << kBarycentricSumSlack << ")";
                throw PluginError(text.str());
            }
        } else {
            const size_t pixel = i / per_pixel;
            const glm::vec2 offset = frame.sample_offsets[i % per_pixel];
            const glm::dvec2 screen(static_cast<double>(pixel % static_cast<size_t>(frame.width)) + offset.x,
                                    static_cast<double>(pixel / static_cast<size_t>(frame.width)) + offset.y);
            bary = solve_barycentrics(triangle, screen, frame.width, frame.height);
            samples.bary[i] = glm::vec3(bary);
        }
        double depth = 0.0;
        for (int k = 0; k < 3; ++k) depth += bary[k] * vertex_view_depth(triangle[static_cast<size_t>(k)], frame);
        if (!std::isfinite(static_cast<float>(depth))) {
            std::ostringstream text;
            text << "plugin " << plugin << " drew triangle " << id << " at " << where(frame, i)
                 << ", where its barycentrics give no finite view depth (" << depth
                 << "): is it a triangle the plugin should have clipped?";
            throw PluginError(text.str());
        }
        samples.view_depth[i] = static_cast<float>(depth);
    }
}

}  // namespace raster::plugin
