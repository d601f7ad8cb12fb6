// The plugin backend: someone's own rasterizer (raster_plugin.h, loaded with `--backend plugin:PATH`) behind the
// renderer seam. The frame's order is raster's (render_frame): the plugin receives the opaque triangles in clip space
// and answers per sample; raster's shading and resolve turn its samples into the image, its transparency pass blends
// the transparent triangles over them and its shadow pass renders the shadow maps. So `raster compare` judges the
// plugin's coverage, depth order and barycentrics sample by sample, and its pixels through raster's shading.
#pragma once

#include <memory>
#include <string>

#include "backends/plugin/plugin_library.h"
#include "raster/frame/raster_backend.h"
#include "raster/frame/renderer.h"

namespace raster::plugin {

// A frame's front end and opaque draw done by the plugin. draw_depth (the shadow maps' faces) is raster's tiled
// backend's: a plugin draws the camera's frame only.
class PluginBackend final : public RasterBackend {
public:
    PluginBackend(const PluginLibrary& library, const Scene& scene);
    // Throws logic_error without draw.geometry; InputError when the plugin refuses the frame, PluginError when it
    // fails or breaks the interface's contract.
    OpaqueDrawStats draw_opaque(const OpaqueDraw& draw, RenderResult& result) const override;
    void draw_depth(const FrameParams& frame, RenderWorkspace& workspace, float* view_depth) const override;

private:
    const PluginLibrary& library_;
    const Scene& scene_;
};

class PluginRenderer final : public Renderer {
public:
    explicit PluginRenderer(std::shared_ptr<const PluginLibrary> library) : library_(std::move(library)) {}
    // "plugin NAME", NAME being what the plugin calls itself.
    std::string name() const override { return "plugin " + library_->name(); }
    bool gives_visibility() const override { return true; }
    // Throws InputError for a scene in precision modes other than the exact ones, PluginRefusal when the plugin
    // refuses the frame, PluginError when it fails or breaks the interface's contract.
    void render_into(const Scene& scene, const RenderOptions& options, RenderResult& result) const override;

private:
    std::shared_ptr<const PluginLibrary> library_;
};

}  // namespace raster::plugin
