// Names of the texture filters and wrap modes, shared by the loaders and the command line.
#include "raster/scene/material.h"

namespace raster {

namespace {
constexpr const char* kFilterNames[] = {"nearest", "bilinear", "trilinear", "anisotropic"};
constexpr const char* kWrapNames[] = {"repeat", "clamp", "mirror"};

template <typename Enum, size_t N>
bool parse_name(const std::string& name, const char* const (&names)[N], Enum& out) {
    for (size_t i = 0; i < N; ++i) {
        if (name == names[i]) {
            out = static_cast<Enum>(i);
            return true;
        }
    }
    return false;
}
}  // namespace

const char* to_string(TextureFilter filter) { return kFilterNames[static_cast<int>(filter)]; }
const char* to_string(TextureWrap wrap) { return kWrapNames[static_cast<int>(wrap)]; }
bool parse_texture_filter(const std::string& name, TextureFilter& out) { return parse_name(name, kFilterNames, out); }
bool parse_texture_wrap(const std::string& name, TextureWrap& out) { return parse_name(name, kWrapNames, out); }

}  // namespace raster
