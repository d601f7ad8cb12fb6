// Small glTF documents for the loader's tests: a buffer built value by value into a data URI, accessors and views
// over it, and the JSON around them, so each test states the one thing it varies.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "raster/gltf/gltf_scene.h"
#include "raster/core/errors.h"

namespace raster::test_support {

class GltfBuilder {
public:
    GltfBuilder() {
        document["asset"] = {{"version", "2.0"}};
        document["scenes"] = nlohmann::json::array({{{"nodes", nlohmann::json::array()}}});
        document["nodes"] = nlohmann::json::array();
        document["meshes"] = nlohmann::json::array();
        document["accessors"] = nlohmann::json::array();
        document["bufferViews"] = nlohmann::json::array();
    }

    // Appends values of type T (float, uint8_t, uint16_t, uint32_t) as a view and an accessor; returns its index.
    template <typename T>
    int accessor(const std::vector<T>& values, const char* type, int component_type, bool normalized = false) {
        while (bytes.size() % 4) bytes.push_back(0);
        const size_t offset = bytes.size();
        bytes.resize(offset + values.size() * sizeof(T));
        std::memcpy(bytes.data() + offset, values.data(), values.size() * sizeof(T));
        const int per = std::string(type) == "SCALAR" ? 1 : type[3] - '0';
        document["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}});
        nlohmann::json a = {{"bufferView", document["bufferViews"].size() - 1}, {"componentType", component_type},
                            {"count", values.size() / per}, {"type", type}};
        if (normalized) a["normalized"] = true;
        document["accessors"].push_back(a);
        return static_cast<int>(document["accessors"].size() - 1);
    }
    int positions(const std::vector<float>& xyz) { return accessor(xyz, "VEC3", 5126); }
    // Appends an image's bytes as a view and the image naming it; returns the image's index.
    int image(const std::string& encoded) {
        while (bytes.size() % 4) bytes.push_back(0);
        document["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bytes.size()}, {"byteLength", encoded.size()}});
        bytes.insert(bytes.end(), encoded.begin(), encoded.end());
        document["images"].push_back({{"bufferView", document["bufferViews"].size() - 1}, {"mimeType", "image/png"}});
        return static_cast<int>(document["images"].size() - 1);
    }

    // A mesh of one primitive; returns the mesh's index.
    int mesh(const nlohmann::json& primitive) {
        document["meshes"].push_back({{"primitives", nlohmann::json::array({primitive})}});
        return static_cast<int>(document["meshes"].size() - 1);
    }
    // A node; a root of scene 0 unless `root` is false. Returns its index.
    int node(const nlohmann::json& fields, bool root = true) {
        document["nodes"].push_back(fields.is_null() ? nlohmann::json::object() : fields);
        const int index = static_cast<int>(document["nodes"].size() - 1);
        if (root) document["scenes"][0]["nodes"].push_back(index);
        return index;
    }
    // One triangle, (0,0,0) (1,0,0) (0,1,0), as mesh 0 of a fresh builder's first node.
    static GltfBuilder one_triangle() {
        GltfBuilder b;
        b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0})}}}})}});
        return b;
    }

    std::string text() const {
        nlohmann::json out = document;
        std::string encoded;
        static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        for (size_t i = 0; i < bytes.size(); i += 3) {
            const uint32_t n = uint32_t{bytes[i]} << 16 | (i + 1 < bytes.size() ? uint32_t{bytes[i + 1]} << 8 : 0) |
                               (i + 2 < bytes.size() ? bytes[i + 2] : 0);
            encoded += table[n >> 18 & 63];
            encoded += table[n >> 12 & 63];
            encoded += i + 1 < bytes.size() ? table[n >> 6 & 63] : '=';
            encoded += i + 2 < bytes.size() ? table[n & 63] : '=';
        }
        if (!bytes.empty())
            out["buffers"] = nlohmann::json::array(
                {{{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + encoded}}});
        return out.dump();
    }

    nlohmann::json document;
    std::vector<uint8_t> bytes;
};

// A reader with no files: any external URI is missing.
inline GltfFileReader no_files() {
    return [](const std::string& path, uint64_t) -> std::string { throw InputError("'" + path + "': no such file"); };
}

// The scene of a builder's document, read as "model.gltf" with no external files.
inline Scene read_built(const GltfBuilder& builder, GltfSceneParts* parts = nullptr) {
    Scene scene;
    const GltfSceneParts got = read_gltf_scene(builder.text(), "model.gltf", no_files(), scene);
    if (parts) *parts = got;
    return scene;
}

// The InputError message reading the builder's document gives; empty when it reads.
inline std::string read_error(const GltfBuilder& builder) {
    try {
        read_built(builder);
    } catch (const InputError& e) {
        return e.message();
    }
    return "";
}

}  // namespace raster::test_support
