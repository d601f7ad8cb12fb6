// Mip chains for a scene's textures (mip_chains.h).
#include "raster/texture/mip_chains.h"

#include <map>
#include <memory>

#include "raster/texture/texture.h"

namespace raster {

namespace {

// Replaces `texture` by a copy with its full chain, one copy per distinct texture (`built`), unless it has one.
void with_full_chain(std::shared_ptr<const Texture>& texture,
                     std::map<const Texture*, std::shared_ptr<const Texture>>& built) {
    const TextureLevel& base = texture->levels.front();
    if (static_cast<int>(texture->levels.size()) == mip_level_count(base.width, base.height)) return;
    auto& slot = built[texture.get()];
    if (!slot) {
        auto full = std::make_shared<Texture>(*texture);
        build_mip_chain(*full);
        slot = std::move(full);
    }
    texture = slot;
}

}  // namespace

void build_needed_mip_chains(Scene& scene) {
    std::map<const Texture*, std::shared_ptr<const Texture>> built;
    for (SceneMesh& mesh : scene.meshes) for_each_material(mesh, [&](Material& material) {
        if (!material.texture || !uses_mip_chain(sampler_of(*material.texture, scene.settings.texture_filter).filter)) return;
        with_full_chain(material.texture->texture, built);
        if (material.texture->reads_alpha) with_full_chain(material.texture->alpha_texture, built);
    });
}

}  // namespace raster
