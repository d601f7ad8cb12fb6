// The transparency properties, on the production renderer: panes facing the camera at distinct depths, each of a
// random colour and opacity (0 and 1 included), drawn in a random order over the background. The pixel every pane
// covers is the panes composited nearest first, computed here in double from the scene's own values
// (docs/transparency.md); a pane of opacity 1 hides everything behind it; and the image does not depend on the draw
// order.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include "properties/failure.h"
#include "properties/generators/primitives.h"
#include "properties/printing.h"
#include "properties/property_registry.h"
#include "properties/stage_driver.h"

namespace raster::properties {

namespace {

struct PaneSpec {
    double depth = 0, half = 0, opacity = 0;
    glm::dvec3 colour{0.0};
};

// Unlit panes on a 16 x 16 image, the camera at (0, 0, 5) looking down -z with a 45-degree field of view.
Scene pane_scene(const std::vector<PaneSpec>& panes, const std::vector<size_t>& order) {
    Scene scene;
    scene.path = "transparency property";
    scene.settings.width = scene.settings.height = 16;
    scene.settings.shading = ShadingMode::unlit;
    scene.settings.background = glm::vec3(0.2f, 0.45f, 0.7f);
    for (size_t i : order) {
        const PaneSpec& p = panes[i];
        SceneMesh mesh;
        const float z = static_cast<float>(5.0 - p.depth), h = static_cast<float>(p.half);
        mutable_data(mesh).positions = {{-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}};
        mutable_data(mesh).triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
        mesh.material.color = glm::vec3(p.colour);
        mesh.material.opacity = static_cast<float>(p.opacity);
        mesh.source = "pane " + std::to_string(i);
        scene.meshes.push_back(mesh);
    }
    return scene;
}

std::string describe(const std::vector<PaneSpec>& panes, const std::vector<size_t>& order) {
    std::string text = "panes (depth, opacity, colour) in draw order:";
    for (size_t i : order)
        text += " (" + double_literal(panes[i].depth) + ", " + double_literal(panes[i].opacity) + ", " +
                literal(glm::vec3(panes[i].colour)) + ")";
    return text;
}

}  // namespace

// The float error of raster's composite: at most 4 layers of 3 operations each on values in [0, 1], each rounding
// by at most 2^-24 of at most 1, plus the stored colours' and opacities' own float rounding: under 64 * 2^-24.
// A byte's exact value within that of a rounding boundary may be written either way.
RASTER_DRAWING_PROPERTY(Transparency, panesCompositeNearestFirstWhateverTheDrawOrder) {
    const int count = *rc::gen::inRange(1, 5);
    std::vector<PaneSpec> panes(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        PaneSpec& p = panes[static_cast<size_t>(i)];
        p.depth = 1.5 + 0.5 * i + 0.3 * (signed_unit() * 0.5 + 0.5);  // distinct: at least 0.2 apart
        p.half = 0.5 + 2.0 * (signed_unit() * 0.5 + 0.5);
        const int kind = *rc::gen::inRange(0, 4);
        p.opacity = kind == 0 ? 0.0 : kind == 1 ? 1.0 : static_cast<double>(static_cast<float>(signed_unit() * 0.5 + 0.5));
        p.colour = glm::dvec3(glm::vec3(static_cast<float>(signed_unit() * 0.5 + 0.5), static_cast<float>(signed_unit() * 0.5 + 0.5),
                                        static_cast<float>(signed_unit() * 0.5 + 0.5)));
    }
    std::vector<size_t> order(panes.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::vector<size_t> shuffled = order;
    for (size_t i = shuffled.size(); i > 1; --i)
        std::swap(shuffled[i - 1], shuffled[static_cast<size_t>(*rc::gen::inRange<size_t>(0, i))]);
    const Scene scene = pane_scene(panes, shuffled);
    const RenderResult result = render_with(impl, scene);
    // The centre pixel's sample (8.5, 8.5) is inside every pane (each reaches past +-0.5 at depth < 4).
    glm::dvec3 colour(0.0);
    double transmittance = 1.0;
    for (const PaneSpec& p : panes) {  // nearest first: panes are generated in depth order
        colour += transmittance * p.opacity * p.colour;
        transmittance *= 1.0 - p.opacity;
    }
    colour += transmittance * glm::dvec3(scene.settings.background);
    const double slack = 64.0 * std::ldexp(1.0, -24);
    const uint8_t* shown = result.image.at(8, 8);
    for (int c = 0; c < 3; ++c) {
        auto byte_of = [](double v) { return static_cast<int>(std::floor(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5)); };
        const int low = byte_of(colour[c] - slack), high = byte_of(colour[c] + slack);
        if (shown[c] < low || shown[c] > high)
            fail_case("centre pixel channel " + std::to_string(c) + " is " + std::to_string(shown[c]) + ", the composite " +
                      double_literal(colour[c]) + " gives " + std::to_string(low) + ".." + std::to_string(high) + "; " +
                      describe(panes, shuffled));
    }
    const RenderResult in_depth_order = render_with(impl, pane_scene(panes, order));
    if (in_depth_order.image.pixels != result.image.pixels)
        fail_case("the image depends on the draw order: " + describe(panes, shuffled) + " against nearest first");
    RC_CLASSIFY(transmittance == 0.0, "an opaque pane hides the rest");
    RC_CLASSIFY(count > 2, "three or four panes");
}

}  // namespace raster::properties
