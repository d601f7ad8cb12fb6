// The bench scenes: loading them, choosing them with --scenes, and creating their llvmpipe peers.
#include "bench/bench_scenes.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <sstream>

#include "raster/compat/scene_loader.h"

namespace raster_bench {

raster::Scene with_samples(const raster::Scene& scene, int samples, bool msaa) {
    raster::Scene copy = scene;
    copy.settings.samples = samples;
    copy.settings.pattern = raster::SamplePattern::standard;
    copy.settings.msaa = msaa;
    return copy;
}

#ifdef RASTER_HAVE_OSMESA
LlvmpipePeer* BenchScene::llvmpipe() {
    if (!peer_tried) {
        peer_tried = true;
        try {
            peer = std::make_unique<LlvmpipePeer>(scene, kThreads);
        } catch (const std::exception& e) {
            peer_error = e.what();
        }
    }
    return peer.get();
}
#endif

std::vector<std::unique_ptr<BenchScene>> load_scenes(const std::vector<std::string>& wanted) {
    std::vector<std::unique_ptr<BenchScene>> scenes;
    for (const SceneSpec& spec : kSceneSpecs) {
        if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), spec.name) == wanted.end()) continue;
        if (!std::filesystem::exists(spec.path)) {
            std::printf("skipping %s: %s not found (the generated scenes are built with raster_bench, or alone with "
                        "`cmake --build BUILD --target bench_meshes`)\n",
                        spec.name, spec.path);
            continue;
        }
        try {
            auto s = std::make_unique<BenchScene>();
            s->name = spec.name;
            s->path = spec.path;
            s->scene = raster::load_scene(spec.path);
            std::printf("scene %-10s %s (%zu triangles)\n", spec.name, spec.path, raster::triangle_count(s->scene));
            scenes.push_back(std::move(s));
        } catch (const std::exception& e) {
            std::printf("skipping %s: %s\n", spec.name, e.what());
        }
    }
    std::fflush(stdout);
    return scenes;
}

std::vector<std::string> take_scenes_flag(std::vector<char*>& args) {
    std::vector<std::string> wanted;
    constexpr const char* kFlag = "--scenes=";
    for (auto it = args.begin(); it != args.end();) {
        if (std::strncmp(*it, kFlag, std::strlen(kFlag)) != 0) {
            ++it;
            continue;
        }
        std::stringstream list(*it + std::strlen(kFlag));
        for (std::string name; std::getline(list, name, ',');)
            if (!name.empty()) wanted.push_back(name);
        it = args.erase(it);
    }
    return wanted;
}

}  // namespace raster_bench
