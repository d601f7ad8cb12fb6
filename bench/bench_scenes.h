// The bench scenes: which there are, loading the ones asked for, and each scene's llvmpipe peer, made on first use.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "raster/scene/scene.h"

#ifdef RASTER_HAVE_OSMESA
#include "bench/llvmpipe_peer.h"
#endif

namespace raster_bench {

inline constexpr int kThreads = 2;  // raster's RenderOptions::threads and llvmpipe's LP_NUM_THREADS

// The scenes, in table order. The teapot is in the corpus; the others are generated at build time into
// RASTER_BENCH_SCENE_DIR (bench/CMakeLists.txt, tools/make_bench_meshes.cpp).
struct SceneSpec {
    const char* name;
    const char* path;
};
inline constexpr SceneSpec kSceneSpecs[] = {
    {"teapot", RASTER_SOURCE_DIR "/corpus/scenes/teapot.yaml"},
    {"organic", RASTER_BENCH_SCENE_DIR "/organic.yaml"},
    {"icosphere", RASTER_BENCH_SCENE_DIR "/icosphere.yaml"},
    {"occlusion", RASTER_BENCH_SCENE_DIR "/occlusion.yaml"},
};

// A copy of `scene` at `samples` standard-pattern samples a pixel, shaded once a pixel per triangle when `msaa`.
raster::Scene with_samples(const raster::Scene& scene, int samples, bool msaa);

// A loaded bench scene and, created on first use, its llvmpipe peer (one OSMesa context per scene).
struct BenchScene {
    std::string name;
    std::string path;
    raster::Scene scene;
#ifdef RASTER_HAVE_OSMESA
    std::unique_ptr<LlvmpipePeer> peer;
    bool peer_tried = false;
    std::string peer_error;

    // Null, with peer_error set, when the peer cannot be created.
    LlvmpipePeer* llvmpipe();
#endif
};

// Loads the scenes asked for (all by default); a missing or unreadable scene is skipped with a message.
std::vector<std::unique_ptr<BenchScene>> load_scenes(const std::vector<std::string>& wanted);

// Takes raster_bench's own flag, --scenes=a,b,... (default: every scene), out of the argument list.
std::vector<std::string> take_scenes_flag(std::vector<char*>& args);

}  // namespace raster_bench
