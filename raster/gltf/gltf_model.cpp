// Untrusted glTF bytes into tinygltf's model (gltf_model.h): the checks before it, the callbacks inside it.
#include "raster/gltf/gltf_model.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <system_error>

#include <nlohmann/json.hpp>

#include "raster/core/errors.h"

namespace raster {
namespace {

constexpr uint32_t kGlbHeaderBytes = 12, kChunkHeaderBytes = 8;
constexpr uint32_t kJsonChunk = 0x4E4F534A;  // "JSON", little-endian

uint32_t little_endian_u32(const char* bytes) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes);
    return uint32_t{b[0]} | uint32_t{b[1]} << 8 | uint32_t{b[2]} << 16 | uint32_t{b[3]} << 24;
}

bool is_glb(std::string_view bytes) { return bytes.size() >= 4 && bytes.substr(0, 4) == "glTF"; }

// The GLB container's JSON chunk, its header and chunk lengths checked against the bytes there are.
std::string_view glb_json_chunk(std::string_view bytes, const std::string& name) {
    if (bytes.size() < kGlbHeaderBytes + kChunkHeaderBytes)
        throw InputError(name, 0, 0, "a GLB file needs a 12-byte header and a chunk; it has " + std::to_string(bytes.size()) + " bytes");
    const uint32_t version = little_endian_u32(bytes.data() + 4), length = little_endian_u32(bytes.data() + 8);
    if (version != 2) throw InputError(name, 0, 0, "GLB version " + std::to_string(version) + "; raster reads version 2");
    if (length > bytes.size())
        throw InputError(name, 0, 0, "the GLB header says " + std::to_string(length) + " bytes; the file has " +
                                         std::to_string(bytes.size()));
    const uint64_t json_length = little_endian_u32(bytes.data() + 12);
    if (little_endian_u32(bytes.data() + 16) != kJsonChunk) throw InputError(name, 0, 0, "the GLB's first chunk is not JSON");
    const uint64_t json_end = kGlbHeaderBytes + kChunkHeaderBytes + json_length;
    if (json_end > length)
        throw InputError(name, 0, 0, "the GLB's JSON chunk of " + std::to_string(json_length) + " bytes runs past its end");
    // A binary chunk, whole: tinygltf 2.7 checks its length without its 8-byte header and would read past the end.
    if (json_end < length) {
        if (json_length % 4 != 0) throw InputError(name, 0, 0, "the GLB's JSON chunk does not end on a 4-byte boundary");
        if (json_end + kChunkHeaderBytes > length)
            throw InputError(name, 0, 0, "the GLB has bytes after its JSON chunk that are no chunk");
        const uint64_t binary_length = little_endian_u32(bytes.data() + json_end);
        if (bytes.substr(json_end + 4, 4) != std::string_view("BIN\0", 4))
            throw InputError(name, 0, 0, "the GLB's second chunk is not BIN");
        if (json_end + kChunkHeaderBytes + binary_length > length)
            throw InputError(name, 0, 0, "the GLB's BIN chunk of " + std::to_string(binary_length) + " bytes runs past its end");
    }
    return bytes.substr(kGlbHeaderBytes + kChunkHeaderBytes, json_length);
}

// tinygltf 2.7 gives every buffer of a GLB without a uri its own copy of the BIN chunk, and throws on an empty one:
// only buffer 0 may leave its uri out, as the spec says.
void check_glb_buffers(std::string_view json, const std::string& name) {
    const nlohmann::json document = nlohmann::json::parse(json.begin(), json.end(), nullptr, false);
    if (!document.is_object() || !document.contains("buffers") || !document["buffers"].is_array()) return;
    const nlohmann::json& buffers = document["buffers"];
    for (size_t i = 0; i < buffers.size(); ++i) {
        if (!buffers[i].is_object() || buffers[i].contains("uri")) continue;
        if (i > 0) throw InputError(name, 0, 0, "/buffers/" + std::to_string(i) + ": only buffer 0 of a GLB may leave out its uri");
        const auto length = buffers[i].find("byteLength");
        if (length == buffers[i].end() || !length->is_number() || !(length->get<double>() >= 1.0))
            throw InputError(name, 0, 0, "/buffers/0/byteLength: the GLB's binary buffer needs a length of at least 1");
    }
}

// tinygltf reads extras and extensions recursively: a deep nesting would overflow the stack, so it is refused first.
void check_json_depth(std::string_view json, const std::string& name) {
    int depth = 0;
    bool in_string = false, escaped = false;
    for (size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (in_string) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxGltfJsonDepth)
                throw InputError(name, 0, 0, "the JSON nests arrays and objects more than " +
                                                 std::to_string(kMaxGltfJsonDepth) + " deep (at byte " + std::to_string(i) + ")");
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

// What the file-system callbacks share: the reader, the bytes still allowed, and why each file failed.
struct FileContext {
    const GltfFileReader* files = nullptr;
    uint64_t remaining = kMaxGltfExternalBytes;
    std::map<std::string, std::string> failures;  // path -> reason
};

std::string same_path(const std::string& path, void*) { return path; }
// Whether a file exists is the reader's to say when it reads it, so that the reason reaches the message.
bool any_file_exists(const std::string&, void*) { return true; }
bool write_nothing(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

bool read_through_reader(std::vector<unsigned char>* out, std::string* error, const std::string& path, void* user) {
    auto& context = *static_cast<FileContext*>(user);
    try {
        const std::string bytes = (*context.files)(path, context.remaining);
        context.remaining -= std::min<uint64_t>(context.remaining, bytes.size());
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const InputError& e) {
        context.failures[path] = e.message();
        if (error) *error = e.message();
        return false;
    }
}

// Images stay encoded. One in a buffer view is not read here: tinygltf hands over its bytes without checking the
// view against its buffer, so gltf_image_bytes reads it, checked, later.
bool keep_encoded(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes,
                  int size, void*) {
    image->as_is = true;
    if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
    return true;
}

// tinygltf's message, one line, at most a few hundred characters.
std::string first_line(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    if (line.size() > 300) line = line.substr(0, 300) + "...";
    return line.empty() ? std::string("tinygltf refused the file") : line;
}

}  // namespace

GltfFileReader gltf_folder_reader(const std::filesystem::path& model) {
    const std::filesystem::path folder = model.parent_path().empty() ? std::filesystem::path(".") : model.parent_path();
    return [folder](const std::string& relative_path, uint64_t max_bytes) {
        std::string portable = relative_path;
        std::replace(portable.begin(), portable.end(), '\\', '/');
        const std::filesystem::path relative = std::filesystem::path(portable).lexically_normal();
        const std::string quoted = "'" + relative_path + "'";
        if (relative.empty() || relative.is_absolute() || relative.has_root_name() || *relative.begin() == "..")
            throw InputError(quoted + " is not a path inside the model's folder; raster reads only files there");
        std::error_code error;
        const std::filesystem::path root = std::filesystem::canonical(folder, error);
        const std::filesystem::path file = std::filesystem::canonical(folder / relative, error);
        if (error) throw InputError(quoted + ": no such file in the model's folder");
        const auto [end, unused] = std::mismatch(root.begin(), root.end(), file.begin(), file.end());
        if (end != root.end()) throw InputError(quoted + " leads outside the model's folder through a link");
        if (!std::filesystem::is_regular_file(file, error)) throw InputError(quoted + " is not a regular file");
        const uint64_t size = std::filesystem::file_size(file, error);
        if (error || size > max_bytes)
            throw InputError(quoted + " has " + std::to_string(size) + " bytes; the model's external files may have " +
                             std::to_string(max_bytes) + " more");
        std::ifstream in(file, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (!in.good() && !in.eof()) throw InputError(quoted + ": cannot be read");
        if (bytes.size() > max_bytes) throw InputError(quoted + " grew past the model's limit while being read");
        return bytes;
    };
}

tinygltf::Model parse_gltf_model(std::string_view bytes, const std::string& name, const GltfFileReader& files) {
    if (bytes.size() > kMaxGltfFileBytes)
        throw InputError(name, 0, 0, "the file has " + std::to_string(bytes.size()) + " bytes; raster reads at most " +
                                         std::to_string(kMaxGltfFileBytes));
    const bool binary = is_glb(bytes);
    const std::string_view json = binary ? glb_json_chunk(bytes, name) : bytes;
    check_json_depth(json, name);
    if (binary) check_glb_buffers(json, name);

    FileContext context;
    context.files = &files;
    tinygltf::FsCallbacks callbacks{};
    callbacks.FileExists = any_file_exists;
    callbacks.ExpandFilePath = same_path;
    callbacks.ReadWholeFile = read_through_reader;
    callbacks.WriteWholeFile = write_nothing;
    callbacks.user_data = &context;
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(callbacks);
    loader.SetImageLoader(keep_encoded, nullptr);

    tinygltf::Model model;
    std::string error, warning;
    const auto size = static_cast<unsigned int>(bytes.size());
    bool loaded = false;
    try {
        loaded = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                                      reinterpret_cast<const unsigned char*>(bytes.data()), size, "")
                        : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), size, "");
    } catch (const std::exception& e) {
        // tinygltf 2.7 indexes some vectors with at(): a malformed file it did not foresee is still the file's fault.
        throw InputError(name, 0, 0, std::string("glTF: tinygltf could not read the file (") + e.what() + ")");
    }
    if (!loaded) {
        // A file the reader refused says why in its own words (the one tinygltf names); else tinygltf's complaint.
        for (const auto& [path, reason] : context.failures)
            if (error.find("File read error : " + path + " ") != std::string::npos)
                throw InputError(name, 0, 0, "a buffer's file " + reason);
        throw InputError(name, 0, 0, "glTF: " + first_line(error));
    }
    for (const auto& [path, reason] : context.failures)
        std::fprintf(stderr, "%s: warning: an image file %s; the textures using it are left out\n", name.c_str(),
                     reason.c_str());
    return model;
}

std::string gltf_image_bytes(const tinygltf::Model& model, int index, const std::string& name) {
    const tinygltf::Image& image = model.images[static_cast<size_t>(index)];
    if (image.bufferView < 0) return std::string(image.image.begin(), image.image.end());
    const std::string where = "/images/" + std::to_string(index) + "/bufferView";
    if (static_cast<size_t>(image.bufferView) >= model.bufferViews.size())
        throw InputError(name, 0, 0, where + ": no buffer view " + std::to_string(image.bufferView));
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(image.bufferView)];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
        throw InputError(name, 0, 0, where + ": its view names no buffer " + std::to_string(view.buffer));
    const std::vector<unsigned char>& data = model.buffers[static_cast<size_t>(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        throw InputError(name, 0, 0, where + ": its view's bytes " + std::to_string(view.byteOffset) + " + " +
                                         std::to_string(view.byteLength) + " run past its buffer's " +
                                         std::to_string(data.size()));
    return std::string(data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset),
                       data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset + view.byteLength));
}

}  // namespace raster
