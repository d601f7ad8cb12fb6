// The bug catalogue (mutants/bugs.txt) read into entries: one planted bug each, where it lives and what shows it.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace raster::mutants {

// A malformed or stale catalogue: the message names the catalogue's file and line.
class CatalogueError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Entry {
    std::string name;     // [name]
    int line = 0;         // the line of its [name] header
    std::string bug;      // one sentence: the mistake
    std::string family;   // the part of the pipeline
    std::string file;     // the production source, relative to the project root
    std::string find;     // exact text, occurring once in file (escapes decoded)
    std::string replace;  // what replaces it (may be empty)
    std::string scene;    // the corpus scene or seed input that shows it
    std::string flags;    // render's settings flags for that scene (may be empty)
    std::string schema;   // optional: the schemata build's text for find, MUTANT standing for the switch
};

struct Catalogue {
    std::filesystem::path path;
    std::vector<Entry> entries;
    const Entry* find(const std::string& name) const;
};

// Reads and validates the format (every key once, required keys present, no plant into oracle/ or harness/).
Catalogue read_catalogue(const std::filesystem::path& path);

// "catalogue.txt:12: [name]" for messages about one entry.
std::string where(const Catalogue& catalogue, const Entry& entry);

}  // namespace raster::mutants
