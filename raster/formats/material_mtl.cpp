// MTL material libraries, read line by line (material_mtl.h).
#include "raster/formats/material_mtl.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "raster/core/errors.h"
#include "raster/formats/mesh_text.h"

namespace raster {

namespace {

using Words = std::vector<std::string_view>;

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Most materials one library may define: far past real files, and a bound on hostile ones.
constexpr size_t kMaxMaterials = 1u << 16;

class MtlReader {
public:
    MtlReader(std::string_view text, const std::string& name, bool strict) : text_(text), name_(name), strict_(strict) {}

    std::vector<MtlMaterial> read() {
        for (size_t start = 0; start < text_.size();) {
            size_t end = text_.find('\n', start);
            if (end == std::string_view::npos) end = text_.size();
            const std::string_view line = text_.substr(start, end - start);
            start = end + 1;
            ++line_;
            read_line(split_words(line, is_blank));
        }
        return std::move(materials_);
    }

private:
    [[noreturn]] void fail(const std::string& message) const {
        throw InputError(name_, static_cast<int>(std::min<int64_t>(line_, INT32_MAX)), 0, message);
    }

    void warn(const std::string& message) const {
        std::fprintf(stderr, "%s:%lld: warning: %s\n", name_.c_str(), static_cast<long long>(line_), message.c_str());
    }

    float number(std::string_view word, float low, float high, const char* what) const {
        const std::string text(word);
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (end != text.c_str() + text.size() || !std::isfinite(value))
            fail(std::string(what) + ": '" + text + "' is not a finite number");
        if (value < low || value > high)
            fail(std::string(what) + " must be in [" + std::to_string(low).substr(0, 3) + ", " +
                 (std::isinf(high) ? std::string("inf") : std::to_string(high).substr(0, 3)) + "], got " + text);
        return static_cast<float>(value);
    }

    MtlMaterial& current(std::string_view keyword) {
        if (materials_.empty()) fail("'" + std::string(keyword) + "' before any newmtl");
        return materials_.back();
    }

    // `Ka r [g b]`: one value is grey.
    std::optional<glm::vec3> color(const Words& words) const {
        if (words.size() < 2) fail(std::string(words[0]) + " needs a colour");
        if (words[1] == "spectral" || words[1] == "xyz") {
            warn(std::string(words[0]) + " " + std::string(words[1]) + " is not read; the default is kept");
            return std::nullopt;
        }
        if (words.size() != 2 && words.size() != 4) fail(std::string(words[0]) + " needs 1 or 3 values");
        const char* what = "a colour";
        const float r = number(words[1], 0.0f, INFINITY, what);
        if (words.size() == 2) return glm::vec3(r);
        return glm::vec3(r, number(words[2], 0.0f, INFINITY, what), number(words[3], 0.0f, INFINITY, what));
    }

    // `map_Kd [-option value...] file`: -clamp is honoured, the other options skipped with their values.
    MtlTextureMap texture_map(const Words& words) const {
        MtlTextureMap map;
        map.line = line_;
        size_t k = 1;
        while (k < words.size() && words[k].size() > 1 && words[k][0] == '-') {
            const std::string option(words[k++]);
            if (option == "-clamp" && k < words.size()) {
                map.clamp = words[k++] == "on";
                continue;
            }
            // -o, -s and -t take up to three numbers, -mm two, the others one.
            const size_t most = option == "-o" || option == "-s" || option == "-t" ? 3 : option == "-mm" ? 2 : 1;
            for (size_t n = 0; n < most && k + 1 < words.size(); ++n) {
                const std::string value(words[k]);
                char* end = nullptr;
                std::strtod(value.c_str(), &end);
                const bool numeric = end == value.c_str() + value.size();
                if (n > 0 && !numeric) break;
                ++k;
            }
            warn("map_Kd option " + option + " is not applied");
        }
        if (k >= words.size()) fail("map_Kd names no image file");
        for (; k < words.size(); ++k) {
            if (!map.file.empty()) map.file += ' ';
            map.file.append(words[k]);
        }
        return map;
    }

    void read_line(const Words& words) {
        if (words.empty() || words[0][0] == '#') return;
        const std::string_view keyword = words[0];
        if (keyword == "newmtl") {
            if (words.size() < 2 && strict_) fail("newmtl needs a name");
            if (words.size() < 2) warn("newmtl without a name: its statements are read, and no usemtl can select it");
            if (materials_.size() >= kMaxMaterials) fail("more than " + std::to_string(kMaxMaterials) + " materials");
            MtlMaterial material;
            material.named = words.size() >= 2;
            for (size_t k = 1; k < words.size(); ++k) {
                if (k > 1) material.name += ' ';
                material.name.append(words[k]);
            }
            material.line = line_;
            materials_.push_back(std::move(material));
        } else if (keyword == "Ka") {
            if (auto c = color(words)) current(keyword).ambient = c;
        } else if (keyword == "Kd") {
            if (auto c = color(words)) current(keyword).diffuse = c;
        } else if (keyword == "Ks") {
            if (auto c = color(words)) current(keyword).specular = c;
        } else if (keyword == "Ns") {
            if (words.size() != 2) fail("Ns needs one value");
            current(keyword).exponent = number(words[1], 0.0f, INFINITY, "Ns");
        } else if (keyword == "d" || keyword == "Tr") {
            // `d -halo f` is the halo form; only the factor is read.
            const size_t at = words.size() == 3 && words[1] == "-halo" ? 2 : 1;
            if (words.size() != at + 1) fail(std::string(keyword) + " needs one value");
            const float value = number(words[at], 0.0f, 1.0f, keyword == "d" ? "d" : "Tr");
            current(keyword).opacity = keyword == "d" ? value : 1.0f - value;
        } else if (keyword == "map_Kd") {
            current(keyword).diffuse_map = texture_map(words);
        }
    }

    std::string_view text_;
    const std::string& name_;
    bool strict_;
    int64_t line_ = 0;
    std::vector<MtlMaterial> materials_;
};

}  // namespace

std::vector<MtlMaterial> parse_mtl(std::string_view text, const std::string& name, bool strict) {
    return MtlReader(text, name, strict).read();
}

}  // namespace raster
