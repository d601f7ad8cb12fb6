// Loading a rasterizer plugin and drawing a frame through it (plugin_library.h).
#include "backends/plugin/plugin_library.h"

#include <dlfcn.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstring>
#include <limits>

#include "backends/plugin/plugin_samples.h"
#include "backends/plugin/raster_plugin.h"
#include "raster/core/errors.h"

namespace raster::plugin {
namespace {

// The library's symbol `name`, or InputError naming what is missing.
void* symbol_of(void* handle, const std::string& path, const char* name) {
    void* found = dlsym(handle, name);
    if (!found)
        throw InputError(path, 0, 0,
                         std::string("this library has no function ") + name +
                             " (a raster plugin exports raster_plugin_abi_version, raster_plugin_name and "
                             "raster_plugin_draw with C linkage; docs/plugins.md)");
    return found;
}

std::string message_of(const std::vector<char>& message) {
    const size_t length = strnlen(message.data(), message.size());
    return length == 0 ? std::string("(no reason given)") : std::string(message.data(), length);
}

}  // namespace

std::shared_ptr<const PluginLibrary> PluginLibrary::open(const std::string& path) {
    struct stat info {};
    if (path.empty() || stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode))
        throw InputError(path, 0, 0, "no plugin library at this path (--backend plugin:PATH names a shared library)");
    // dlopen searches the library path for a name without a slash; the user named a file.
    const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* reason = dlerror();
        throw InputError(path, 0, 0, std::string("cannot load this plugin: ") + (reason ? reason : "dlopen failed"));
    }
    PluginFunctions functions;
    try {
        functions.abi_version = reinterpret_cast<uint32_t (*)()>(symbol_of(handle, path, "raster_plugin_abi_version"));
        functions.name = reinterpret_cast<const char* (*)()>(symbol_of(handle, path, "raster_plugin_name"));
        functions.draw = reinterpret_cast<int (*)(const raster_plugin_frame*, raster_plugin_samples*)>(
            symbol_of(handle, path, "raster_plugin_draw"));
        auto library = std::make_shared<PluginLibrary>(functions, path);
        library->handle_ = handle;
        return library;
    } catch (...) {
        dlclose(handle);
        throw;
    }
}

PluginLibrary::PluginLibrary(const PluginFunctions& functions, std::string origin)
    : functions_(functions), origin_(std::move(origin)) {
    const uint32_t version = functions_.abi_version();
    if (version != RASTER_PLUGIN_ABI_VERSION)
        throw InputError(origin_, 0, 0,
                         "this plugin was built against version " + std::to_string(version) +
                             " of raster_plugin.h; this raster speaks version " +
                             std::to_string(RASTER_PLUGIN_ABI_VERSION) + ": rebuild it against this raster's header");
    const char* name = functions_.name();
    name_ = name && *name ? name : origin_;
}

PluginLibrary::~PluginLibrary() {
    if (handle_) dlclose(handle_);
}

void PluginLibrary::draw(const ClipSpaceFrame& frame, VisibilityBuffer& out) const {
    static_assert(sizeof(glm::vec2) == 2 * sizeof(float) && sizeof(glm::vec3) == 3 * sizeof(float) &&
                  sizeof(glm::vec4) == 4 * sizeof(float));
    static_assert(RASTER_PLUGIN_NO_TRIANGLE == kNoTriangle);
    const int samples = static_cast<int>(frame.sample_offsets.size());
    out.resize(frame.width, frame.height, samples);
    // NaN until written, so that a plugin claiming barycentrics it left out is caught (complete_samples).
    std::fill(out.bary.begin(), out.bary.end(), glm::vec3(std::numeric_limits<float>::quiet_NaN()));

    raster_plugin_frame in{};
    in.abi_version = RASTER_PLUGIN_ABI_VERSION;
    in.width = frame.width;
    in.height = frame.height;
    in.samples = samples;
    in.sample_offsets = reinterpret_cast<const float*>(frame.sample_offsets.data());
    in.subpixel_bits = frame.subpixel_bits;
    in.cull_backfaces = frame.cull_backfaces;
    in.orthographic = frame.orthographic;
    in.near_plane = frame.near_plane;
    in.far_plane = frame.far_plane;
    in.triangle_count = static_cast<uint32_t>(frame.triangles.size());
    in.clip_positions = reinterpret_cast<const float*>(frame.triangles.data());

    std::vector<char> message(RASTER_PLUGIN_MESSAGE_SIZE, '\0');
    raster_plugin_samples answer{};
    answer.triangle = out.triangle.data();
    answer.barycentrics = reinterpret_cast<float*>(out.bary.data());
    answer.message = message.data();
    message.back() = '\0';

    const int status = functions_.draw(&in, &answer);
    message.back() = '\0';  // whatever the plugin wrote, the message ends inside its buffer
    if (status == RASTER_PLUGIN_REFUSED)
        throw PluginRefusal("plugin " + name_ + " does not draw this frame: " + message_of(message));
    if (status != RASTER_PLUGIN_DRAWN)
        throw PluginError("plugin " + name_ + " failed (raster_plugin_draw returned " + std::to_string(status) +
                          "): " + message_of(message));
    complete_samples(frame, answer.barycentrics_written != 0, name_, out);
}

}  // namespace raster::plugin
