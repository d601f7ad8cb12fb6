// Reads mutants/bugs.txt: [name] sections of `key = value` lines, with \n \t \s \\ escapes in find, replace and schema.
#include "mutants/catalogue.h"

#include <fstream>
#include <map>
#include <regex>
#include <set>

namespace raster::mutants {
namespace {

const std::vector<std::string> kKeys = {"bug", "family", "file", "find", "replace", "scene", "flags", "schema"};
const std::set<std::string> kOptional = {"schema"};
const std::set<std::string> kMayBeEmpty = {"replace", "flags", "schema", "family"};
const std::set<std::string> kEscaped = {"find", "replace", "schema"};

std::string trim(const std::string& text) {
    const size_t begin = text.find_first_not_of(" \t\r");
    if (begin == std::string::npos) return "";
    const size_t end = text.find_last_not_of(" \t\r");
    return text.substr(begin, end - begin + 1);
}

// Decodes \n \t \s \\; returns false on any other escape.
bool unescape(const std::string& text, std::string& out) {
    out.clear();
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\\') {
            out += text[i];
            continue;
        }
        if (++i == text.size()) return false;
        switch (text[i]) {
            case 'n': out += '\n'; break;
            case 't': out += '\t'; break;
            case 's': out += ' '; break;
            case '\\': out += '\\'; break;
            default: return false;
        }
    }
    return true;
}

// The member a key sets (null for an unknown key); E is Entry or const Entry.
template <typename E>
auto field(E& entry, const std::string& key) -> decltype(&entry.bug) {
    if (key == "bug") return &entry.bug;
    if (key == "family") return &entry.family;
    if (key == "file") return &entry.file;
    if (key == "find") return &entry.find;
    if (key == "replace") return &entry.replace;
    if (key == "scene") return &entry.scene;
    if (key == "flags") return &entry.flags;
    if (key == "schema") return &entry.schema;
    return nullptr;
}

}  // namespace

const Entry* Catalogue::find(const std::string& name) const {
    for (const Entry& entry : entries)
        if (entry.name == name) return &entry;
    return nullptr;
}

std::string where(const Catalogue& catalogue, const Entry& entry) {
    return catalogue.path.string() + ":" + std::to_string(entry.line) + ": [" + entry.name + "]";
}

Catalogue read_catalogue(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw CatalogueError(path.string() + ": cannot read the catalogue");
    Catalogue catalogue{path, {}};
    std::map<std::string, std::set<std::string>> seen;  // the keys each entry has set
    const std::regex header(R"(^\[([A-Za-z0-9_-]+)\]\s*$)");
    const std::regex pair(R"(^([a-z]+)\s*=(.*)$)");
    std::string line;
    int number = 0;
    auto fail = [&](const std::string& message) {
        throw CatalogueError(path.string() + ":" + std::to_string(number) + ": " + message);
    };
    while (std::getline(in, line)) {
        ++number;
        const std::string trimmed = trim(line);
        if (trimmed.empty() || trimmed[0] == '#') continue;
        std::smatch match;
        if (std::regex_match(line, match, header)) {
            if (catalogue.find(match[1])) fail("entry [" + match[1].str() + "] appears twice");
            Entry entry;
            entry.name = match[1];
            entry.line = number;
            catalogue.entries.push_back(entry);
            continue;
        }
        if (!std::regex_match(line, match, pair)) fail("expected [name], 'key = value' or a comment");
        const std::string key = match[1];
        std::string value = trim(match[2]);
        if (catalogue.entries.empty()) fail("'" + key + "' before the first [name]");
        Entry& entry = catalogue.entries.back();
        auto* slot = field(entry, key);
        if (!slot) fail("unknown key '" + key + "' (keys: bug family file find replace scene flags schema)");
        if (!seen[entry.name].insert(key).second) fail("[" + entry.name + "] sets '" + key + "' twice");
        if (kEscaped.count(key) && !unescape(value, *slot))
            fail("[" + entry.name + "] " + key + ": unknown escape (only \\n \\t \\s \\\\)");
        if (!kEscaped.count(key)) *slot = value;
    }
    if (catalogue.entries.empty()) throw CatalogueError(path.string() + ": no entries");
    for (const Entry& entry : catalogue.entries) {
        for (const std::string& key : kKeys) {
            const bool set = seen[entry.name].count(key) > 0;
            if (!set && !kOptional.count(key))
                throw CatalogueError(where(catalogue, entry) + " has no '" + key + "'");
            if (set && !kMayBeEmpty.count(key) && field(entry, key)->empty())
                throw CatalogueError(where(catalogue, entry) + " has an empty '" + key + "'");
        }
        if (entry.file.rfind("oracle/", 0) == 0 || entry.file.rfind("harness/", 0) == 0)
            throw CatalogueError(where(catalogue, entry) + " plants into " + entry.file +
                                 ": bugs belong in the production path, not in the checks");
    }
    return catalogue;
}

}  // namespace raster::mutants
