// The schemata build's source: every catalogue entry of a file compiled in behind a runtime switch, so one build
// holds every bug and the environment picks which one runs (mutant schemata).
#pragma once

#include <string>
#include <vector>

#include "mutants/catalogue.h"

namespace raster::mutants {

// The text that replaces an entry's region in the schemata build: `correct` is the region as the correct build
// compiles it (the find text, with any entries nested inside it already switched), `on` the C++ expression that is
// true when this entry is switched on, `before` the last character before the region in the file (not a blank or
// a comment; '\0' at the start). The form follows the find text: a declaration `T x = a;` becomes
// `T x = on ? (b) : (a);` (`T x{a};` becomes `T x = on ? T{b} : T{a};`), a statement that starts one
// `if (on) { replace } else { find }`, an expression or a statement's tail `(on ? (b) : (a))`; an entry whose find
// text is none of these must give its own `schema`. Throws CatalogueError naming the entry.
std::string switched_text(const Catalogue& catalogue, const Entry& entry, const std::string& correct,
                          const std::string& on, char before = '\0');

// One entry placed in a file: its index (the switch's site number) and where its find text starts.
struct Site {
    const Entry* entry;
    int index;
};

// The whole file with every site switched in. Each entry's find text must occur exactly once in `original`; two
// entries' regions must be equal or nested, never partly overlapping.
std::string schemata_source(const Catalogue& catalogue, const std::string& original, const std::vector<Site>& sites,
                            const std::string& switch_header);

// The C++ expression that tests site `index`.
std::string switch_expression(int index);

}  // namespace raster::mutants
