// Wavefront MTL material libraries: the statements raster draws with (newmtl, Ka, Kd, Ks, Ns, d, Tr, map_Kd).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace raster {

// A map_Kd statement: the image file (relative to the MTL's folder) and the line that names it.
struct MtlTextureMap {
    std::string file;
    int64_t line = 0;
    bool clamp = false;  // `-clamp on`: coordinates outside [0, 1] read the edge
};

// One `newmtl` block; each value present only when the block sets it.
struct MtlMaterial {
    std::string name;
    bool named = true;  // false for a `newmtl` without a name (read leniently): no usemtl can select it
    int64_t line = 0;
    std::optional<glm::vec3> ambient, diffuse, specular;  // Ka, Kd, Ks
    std::optional<float> exponent;                        // Ns
    std::optional<float> opacity;                         // d, or 1 - Tr
    std::optional<MtlTextureMap> diffuse_map;             // map_Kd
};

// Parses MTL text; `name` names the file in messages. Statements raster does not draw with (illum, Ni, Ke, the other
// maps...) are skipped; a colour given as `spectral` or `xyz`, and map_Kd options other than -clamp, are skipped
// with a warning on stderr. Throws InputError, with the line, for a value that is not a finite number, a negative
// colour or Ns, an opacity outside [0, 1], a statement before the first newmtl, or a map_Kd without a file. A
// `newmtl` without a name is an error when `strict`; otherwise it starts a material no usemtl can select, with a
// warning, as assimp and viewers read such files.
std::vector<MtlMaterial> parse_mtl(std::string_view text, const std::string& name, bool strict = false);

}  // namespace raster
