// Untrusted glTF files: external files only from the model's folder and below (no '..', no absolute path, no link
// out), under a size cap; the GLB container's lengths checked; deep JSON refused before tinygltf recurses into it;
// a missing buffer refused naming it, a missing image left out with the model still drawn.
#include "raster/gltf/gltf_model.h"

#include <fstream>

#include <gtest/gtest.h>

#include "raster/compat/scene_loader.h"
#include "raster/texture/texture.h"
#include "tests/support/temp_dir.h"
#include "tests/support/gltf_builder.h"

namespace raster {
namespace {

using test_support::GltfBuilder;
using test_support::TempDir;

std::string refusal(const GltfFileReader& read, const std::string& path, uint64_t cap = 1 << 20) {
    try {
        read(path, cap);
    } catch (const InputError& e) {
        return e.message();
    }
    return "";
}

TEST(GltfModel, theFolderReaderReadsOnlyFilesInsideTheModelsFolder) {
    TempDir dir;
    dir.write("models/buffers/data.bin", "inside");
    dir.write("secret.bin", "outside");
    const GltfFileReader read = gltf_folder_reader(dir / "models/model.gltf");
    EXPECT_EQ(read("buffers/data.bin", 100), "inside");
    EXPECT_EQ(read("buffers\\data.bin", 100), "inside");  // a Windows exporter's separators
    EXPECT_EQ(read("buffers/../buffers/data.bin", 100), "inside");
    EXPECT_NE(refusal(read, "../secret.bin").find("not a path inside the model's folder"), std::string::npos);
    EXPECT_NE(refusal(read, "buffers/../../secret.bin").find("not a path inside"), std::string::npos);
    EXPECT_NE(refusal(read, (dir / "secret.bin").string()).find("not a path inside"), std::string::npos);
    EXPECT_NE(refusal(read, "missing.bin").find("no such file"), std::string::npos);
    EXPECT_NE(refusal(read, "buffers").find("not a regular file"), std::string::npos);
    EXPECT_NE(refusal(read, "buffers/data.bin", 3).find("has 6 bytes"), std::string::npos);
    std::filesystem::create_symlink(dir / "secret.bin", dir / "models/link.bin");
    EXPECT_NE(refusal(read, "link.bin").find("outside the model's folder through a link"), std::string::npos);
}

TEST(GltfModel, aMissingBufferFileIsRefusedNamingIt) {
    GltfBuilder b = GltfBuilder::one_triangle();
    std::string text = b.text();
    nlohmann::json document = nlohmann::json::parse(text);
    document["buffers"][0]["uri"] = "gone.bin";
    try {
        parse_gltf_model(document.dump(), "model.gltf", test_support::no_files());
        FAIL() << "read a model whose buffer is missing";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "model.gltf");
        EXPECT_NE(e.message().find("'gone.bin': no such file"), std::string::npos) << e.message();
    }
}

TEST(GltfModel, aMissingImageLeavesTheTextureOutAndTheModelDrawn) {
    TempDir dir;
    GltfBuilder b = GltfBuilder::one_triangle();
    b.document["meshes"][0]["primitives"][0]["material"] = 0;
    b.document["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    b.document["textures"] = {{{"source", 0}}};
    b.document["images"] = {{{"uri", "missing.png"}}};
    const std::filesystem::path model = dir.write("model.gltf", b.text());
    const Scene scene = load_scene(model);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_FALSE(scene.meshes[0].material.texture);
}

TEST(GltfModel, anEmbeddedImageKeepsItsBytesForTheOracle) {
    std::ifstream in(std::string(RASTER_SOURCE_DIR) + "/corpus/gltf/textured_quad.glb", std::ios::binary);
    const std::string glb((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const Scene scene = parse_scene(glb, std::string(RASTER_SOURCE_DIR) + "/corpus/gltf/textured_quad.glb");
    ASSERT_EQ(scene.meshes.size(), 1u);
    const auto& binding = scene.meshes[0].material.texture;
    ASSERT_TRUE(binding);
    ASSERT_TRUE(binding->encoded);
    std::ifstream png(std::string(RASTER_SOURCE_DIR) + "/corpus/textures/checker.png", std::ios::binary);
    EXPECT_EQ(*binding->encoded, std::string((std::istreambuf_iterator<char>(png)), std::istreambuf_iterator<char>()));
    EXPECT_EQ(binding->filter, TextureFilter::nearest);
    EXPECT_EQ(binding->texture->levels[0].width, 240);
}

// A GLB of `json` and an optional binary chunk, its header lengths as the spec gives them.
std::string glb(std::string json, const std::string& binary = "") {
    while (json.size() % 4) json += ' ';
    const auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    std::string chunks = u32(static_cast<uint32_t>(json.size())) + "JSON" + json;
    if (!binary.empty()) chunks += u32(static_cast<uint32_t>(binary.size())) + std::string("BIN\0", 4) + binary;
    return "glTF" + u32(2) + u32(static_cast<uint32_t>(12 + chunks.size())) + chunks;
}

std::string glb_refusal(const std::string& bytes) {
    try {
        parse_gltf_model(bytes, "model.glb", test_support::no_files());
    } catch (const InputError& e) {
        return e.message();
    }
    return "";
}

TEST(GltfModel, aGlbsLengthsAreCheckedBeforeTinygltfReadsIt) {
    const std::string good = glb(GltfBuilder::one_triangle().text());
    EXPECT_EQ(glb_refusal(good), "");
    std::string version = good;
    version[4] = 1;
    EXPECT_NE(glb_refusal(version).find("GLB version 1"), std::string::npos);
    std::string long_header = good;
    long_header[8] = static_cast<char>(long_header[8] + 4);
    EXPECT_NE(glb_refusal(long_header).find("the GLB header says"), std::string::npos) << glb_refusal(long_header);
    std::string long_chunk = good;
    long_chunk[12] = static_cast<char>(long_chunk[12] + 8);
    EXPECT_NE(glb_refusal(long_chunk).find("runs past its end"), std::string::npos) << glb_refusal(long_chunk);
    EXPECT_NE(glb_refusal(good.substr(0, 15)).find("12-byte header"), std::string::npos);
    // A BIN chunk whose stated length, with its 8-byte header, runs past the file (tinygltf 2.7 would read 8 bytes
    // past it): the last 4 of its 12 bytes are missing.
    nlohmann::json document = nlohmann::json::parse(GltfBuilder::one_triangle().text());
    document["buffers"][0].erase("uri");
    std::string short_binary = glb(document.dump(), std::string(44, '\0'));
    const size_t length_at = short_binary.size() - 44 - 8;
    short_binary[length_at] = 48;
    EXPECT_NE(glb_refusal(short_binary).find("BIN chunk of 48 bytes runs past its end"), std::string::npos)
        << glb_refusal(short_binary);
    EXPECT_EQ(glb_refusal(glb(document.dump(), std::string(44, '\0'))), "");
}

TEST(GltfModel, onlyAGlbsFirstBufferMayLeaveOutItsUri) {
    nlohmann::json document = nlohmann::json::parse(GltfBuilder::one_triangle().text());
    document["buffers"][0].erase("uri");
    document["buffers"].push_back({{"byteLength", 44}});
    EXPECT_NE(glb_refusal(glb(document.dump(), std::string(44, '\0'))).find("/buffers/1: only buffer 0"), std::string::npos);
    // tinygltf 2.7 throws std::out_of_range on an empty binary buffer: refused as the file's error first.
    document["buffers"] = {{{"byteLength", 0}}};
    EXPECT_NE(glb_refusal(glb(document.dump(), std::string(44, '\0'))).find("/buffers/0/byteLength"), std::string::npos);
}

TEST(GltfModel, deeplyNestedJsonIsRefusedBeforeTinygltfRecursesIntoIt) {
    GltfBuilder b = GltfBuilder::one_triangle();
    std::string text = b.text();
    const std::string nested = std::string(kMaxGltfJsonDepth, '[') + std::string(kMaxGltfJsonDepth, ']');
    text.insert(text.size() - 1, ",\"extras\":" + nested);
    EXPECT_NE(glb_refusal(glb(text)).find("nests arrays and objects more than 64 deep"), std::string::npos);
    // Brackets inside strings do not count.
    std::string quoted = b.text();
    quoted.insert(quoted.size() - 1, ",\"extras\":\"" + nested + "\"");
    EXPECT_EQ(glb_refusal(glb(quoted)), "");
}

TEST(GltfModel, anImageViewPastItsBufferIsRefused) {
    GltfBuilder b = GltfBuilder::one_triangle();
    b.document["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 30}, {"byteLength", 100}});
    b.document["images"] = {{{"bufferView", 1}, {"mimeType", "image/png"}}};
    const tinygltf::Model model = parse_gltf_model(b.text(), "model.gltf", test_support::no_files());
    try {
        gltf_image_bytes(model, 0, "model.gltf");
        FAIL() << "read an image past its buffer";
    } catch (const InputError& e) {
        EXPECT_NE(e.message().find("/images/0/bufferView"), std::string::npos) << e.message();
    }
}

}  // namespace
}  // namespace raster
