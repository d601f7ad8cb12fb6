// The registry RASTER_PROPERTY and RASTER_DRAWING_PROPERTY fill, and the one order every run lists the properties in.
#include "properties/property_registry.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <tuple>

namespace raster::properties {
namespace {

// The suites in the order of docs/properties.md. Static initialisation runs the sources in whatever order the linker chose, so
// the registry is sorted by this list (and within a suite by where each property is written) to stay the same
// from build to build. A new suite is added here.
const char* const kSuiteOrder[] = {
    "Watertight", "Coverage", "FillRule", "Barycentrics", "Depth", "ViewMatrix", "Projection", "Matrices",
    "ModelMatrix", "Instancing", "PrimitiveModes", "Animation", "NormalMatrix", "Clip", "Sampling", "Extremes", "Lighting", "MipChain", "Wrap", "Trilinear",
    "LevelOfDetail", "Texture", "Shadow", "Transparency",
};

// A function's static, so that it exists before the first RASTER_PROPERTY of any source registers into it.
std::vector<Property>& registered() {
    static std::vector<Property> properties;
    return properties;
}

size_t suite_rank(const std::string& suite) {
    const auto found = std::find(std::begin(kSuiteOrder), std::end(kSuiteOrder), suite);
    if (found == std::end(kSuiteOrder))
        throw std::logic_error("property suite " + suite + " is not in kSuiteOrder (properties/property_registry.cpp)");
    return static_cast<size_t>(found - std::begin(kSuiteOrder));
}

}  // namespace

bool register_property(const char* suite, const char* name, void (*check)(const Implementation&), bool draws,
                       bool any_renderer, const char* file, int line) {
    registered().push_back({suite, name, check, draws, any_renderer, file, line});
    return true;
}

const std::vector<Property>& all_properties() {
    static const std::vector<Property> sorted = [] {
        std::vector<std::tuple<size_t, std::string, int, const Property*>> keys;
        for (const Property& p : registered()) keys.emplace_back(suite_rank(p.suite), p.file, p.line, &p);
        std::sort(keys.begin(), keys.end());
        std::vector<Property> properties;
        for (const auto& key : keys) properties.push_back(*std::get<3>(key));
        return properties;
    }();
    return sorted;
}

}  // namespace raster::properties
