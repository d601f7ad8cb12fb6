// make_bench_meshes: writes the benchmark meshes (icosphere, organic scanned-like blob, stacked occluding layers)
// as deterministic binary little-endian PLY files with per-vertex normals.
//
// Usage: make_bench_meshes OUT_DIR
//
// Writes OUT_DIR/icosphere.ply, OUT_DIR/organic.ply and OUT_DIR/occlusion.ply, each atomically (OUT.tmp, then
// renamed). Every mesh is closed or single-sided as its header says, counter-clockwise seen from the side its
// normals point to (raster's and OpenGL's front faces). The output is byte-identical on every run: the only
// randomness is a fixed-seed SplitMix64 stream, and every number is computed in double and rounded once to float.
//
// Exit codes: 0 success, 1 a mesh failed its checks or an output could not be written, 2 bad usage.

#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "tools/bench_mesh.h"
#include "tools/icosphere_mesh.h"
#include "tools/occlusion_mesh.h"
#include "tools/organic_mesh.h"
#include "tools/ply_writer.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitWriteError = 1;
constexpr int kExitUsage = 2;

using namespace raster::tools;  // the meshes, their checks and the PLY writer

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 || std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help") {
        std::cerr << "usage: make_bench_meshes OUT_DIR   (writes icosphere.ply, organic.ply, occlusion.ply)\n";
        return argc == 2 ? kExitOk : kExitUsage;
    }
    const std::filesystem::path out_dir = argv[1];
    std::error_code error;
    std::filesystem::create_directories(out_dir, error);
    if (error) {
        std::cerr << "make_bench_meshes: cannot create " << out_dir.string() << ": " << error.message() << "\n";
        return kExitWriteError;
    }

    auto away_from_origin = [](Vec3 centroid) { return centroid; };
    auto towards_camera = [](Vec3) { return Vec3{0, 0, 1}; };

    struct Output {
        const char* file;
        Mesh mesh;
        std::string comment;
        bool valid;
    };
    std::vector<Output> outputs;
    {
        Mesh icosphere = make_icosphere(6);
        const bool valid = check_mesh("icosphere", icosphere, away_from_origin);
        outputs.push_back({"icosphere.ply", std::move(icosphere),
                           "icosahedron subdivided 6 times, unit radius, normals = positions", valid});
    }
    {
        Mesh organic = make_organic(OrganicParams{});
        const bool valid = check_mesh("organic", organic, away_from_origin);
        outputs.push_back({"organic.ply", std::move(organic),
                           "noise-displaced jittered cube sphere, area-weighted vertex normals", valid});
    }
    {
        const OcclusionParams params;
        Mesh occlusion = make_occlusion(params);
        const bool valid = check_mesh("occlusion", occlusion, towards_camera);
        outputs.push_back({"occlusion.ply", std::move(occlusion),
                           std::to_string(params.layers) + " wavy sheets facing +z, farthest first", valid});
    }

    int status = kExitOk;
    for (const Output& output : outputs) {
        if (!output.valid) {
            std::cerr << "make_bench_meshes: " << output.file << " fails its checks; not written\n";
            status = kExitWriteError;
            continue;
        }
        if (!write_atomically(out_dir / output.file, ply_bytes(output.mesh, output.comment))) status = kExitWriteError;
    }
    return status;
}
