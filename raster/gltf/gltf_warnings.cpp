// A model's warnings, each said once (gltf_warnings.h).
#include "raster/gltf/gltf_warnings.h"

#include <cstdio>

namespace raster {

void GltfWarnings::say(const std::string& message) {
    if (said_.insert(message).second) std::fprintf(stderr, "%s: warning: %s\n", file_.c_str(), message.c_str());
}

}  // namespace raster
