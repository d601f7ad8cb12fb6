// Internal to raster_formats (the OBJ and PLY readers): splitting a line of mesh text into its words.
#pragma once

#include <string_view>
#include <vector>

namespace raster {

// The words of `line`: the runs of characters between those for which is_separator(c) holds.
template <class IsSeparator>
std::vector<std::string_view> split_words(std::string_view line, IsSeparator is_separator) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && is_separator(line[i])) ++i;
        const size_t start = i;
        while (i < line.size() && !is_separator(line[i])) ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

}  // namespace raster
