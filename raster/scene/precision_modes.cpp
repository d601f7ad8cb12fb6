// Names of the precision modes, both ways.
#include "raster/scene/precision_modes.h"

#include <array>
#include <utility>

namespace raster {
namespace {

template <class Enum, size_t N>
using NameTable = std::array<std::pair<Enum, const char*>, N>;

constexpr NameTable<EdgeArithmetic, 2> kEdgeNames{{{EdgeArithmetic::fixed, "fixed"}, {EdgeArithmetic::float32, "float"}}};
constexpr NameTable<Interpolation, 2> kInterpolationNames{
    {{Interpolation::perspective, "perspective"}, {Interpolation::affine, "affine"}}};
constexpr NameTable<DepthFormat, 3> kDepthNames{
    {{DepthFormat::reversed_z, "reversed-z"}, {DepthFormat::float_z, "float"}, {DepthFormat::fixed24, "fixed24"}}};
constexpr NameTable<Clipping, 2> kClippingNames{{{Clipping::full, "full"}, {Clipping::guard_band, "guard-band"}}};

template <class Enum, size_t N>
const char* name_of(const NameTable<Enum, N>& table, Enum value) {
    for (const auto& [v, name] : table)
        if (v == value) return name;
    return "?";
}

template <class Enum, size_t N>
bool parse(const NameTable<Enum, N>& table, const std::string& name, Enum& out) {
    for (const auto& [v, n] : table)
        if (name == n) {
            out = v;
            return true;
        }
    return false;
}

template <class Enum, size_t N>
std::string names(const NameTable<Enum, N>& table) {
    std::string text;
    for (const auto& [v, n] : table) {
        if (!text.empty()) text.append(", ");
        text.append(n);
    }
    return text;
}

}  // namespace

const char* to_string(EdgeArithmetic v) { return name_of(kEdgeNames, v); }
const char* to_string(Interpolation v) { return name_of(kInterpolationNames, v); }
const char* to_string(DepthFormat v) { return name_of(kDepthNames, v); }
const char* to_string(Clipping v) { return name_of(kClippingNames, v); }
bool parse_edge_arithmetic(const std::string& name, EdgeArithmetic& out) { return parse(kEdgeNames, name, out); }
bool parse_interpolation(const std::string& name, Interpolation& out) { return parse(kInterpolationNames, name, out); }
bool parse_depth_format(const std::string& name, DepthFormat& out) { return parse(kDepthNames, name, out); }
bool parse_clipping(const std::string& name, Clipping& out) { return parse(kClippingNames, name, out); }
std::string edge_arithmetic_names() { return names(kEdgeNames); }
std::string interpolation_names() { return names(kInterpolationNames); }
std::string depth_format_names() { return names(kDepthNames); }
std::string clipping_names() { return names(kClippingNames); }

bool exact_precision(const PrecisionModes& modes) {
    const PrecisionModes exact;
    return modes.edges == exact.edges && modes.interpolation == exact.interpolation && modes.depth == exact.depth &&
           modes.clipping == exact.clipping;
}

}  // namespace raster
