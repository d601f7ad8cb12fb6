// llvmpipe_render SCENE OUT.png: llvmpipe's whole process for one frame, as `raster render` does it: load the scene
// (raster's loader), draw it once through OSMesa with 2 threads, write the PNG (raster's encoder), exit. The peer
// process process_bench times raster's against.
#include <cstdio>
#include <exception>

#include "bench/llvmpipe_peer.h"
#include "raster/compat/scene_loader.h"
#include "raster/image/image.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: llvmpipe_render SCENE OUT.png\n");
        return 2;
    }
    try {
        const raster::Scene scene = raster::load_scene(argv[1]);
        raster_bench::LlvmpipePeer peer(scene, 2);
        peer.draw_frame();
        const std::vector<uint8_t> rgba = peer.image_top_down();
        raster::Image image(scene.settings.width, scene.settings.height, 3);
        for (size_t pixel = 0; pixel < rgba.size() / 4; ++pixel)
            for (int c = 0; c < 3; ++c) image.pixels[pixel * 3 + c] = rgba[pixel * 4 + c];
        raster::write_image(argv[2], image);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "llvmpipe_render: %s\n", e.what());
        return 1;
    }
    return 0;
}
