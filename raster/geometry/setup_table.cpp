// Setup references: the table of parts, over the front end's chunks or over one list.
#include "raster/geometry/setup_table.h"

#include <algorithm>
#include <stdexcept>

namespace raster {

SetupTable SetupTable::of_chunks(const std::vector<std::vector<TriangleSetup>>& chunks) {
    if (chunks.size() > kMaxSetupParts) throw std::length_error("more setup chunks than setup references can name");
    SetupTable table;
    table.parts_.reserve(chunks.size());
    table.sizes_.reserve(chunks.size());
    for (const std::vector<TriangleSetup>& chunk : chunks) {
        if (chunk.size() >= kSetupsPerPart) throw std::length_error("a setup chunk larger than a part");
        table.parts_.push_back(chunk.data());
        table.sizes_.push_back(static_cast<uint32_t>(chunk.size()));
    }
    return table;
}

SetupTable SetupTable::of_list(const std::vector<TriangleSetup>& setups) {
    if (setups.size() >= kNoTriangle) throw std::length_error("more setups than setup references can name");
    SetupTable table;
    for (size_t first = 0; first < setups.size(); first += kSetupsPerPart) {
        table.parts_.push_back(setups.data() + first);
        table.sizes_.push_back(static_cast<uint32_t>(std::min<size_t>(kSetupsPerPart, setups.size() - first)));
    }
    return table;
}

}  // namespace raster
