// Mutant schemata: each entry's find text rewritten as a runtime switch between the correct code and the bug.
#include "mutants/schema.h"

#include <algorithm>
#include <cctype>
#include <regex>

namespace raster::mutants {
namespace {

// Brackets balance (never closing more than opened) outside string and character literals and comments.
bool balanced(const std::string& text) {
    std::string open;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '"' || c == '\'') {
            for (++i; i < text.size() && text[i] != c; ++i)
                if (text[i] == '\\') ++i;
            continue;
        }
        if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            i = text.find('\n', i);
            if (i == std::string::npos) break;
            continue;
        }
        if (c == '(' || c == '[' || c == '{') open += c;
        if (c == ')' || c == ']' || c == '}') {
            const char want = c == ')' ? '(' : c == ']' ? '[' : '{';
            if (open.empty() || open.back() != want) return false;
            open.pop_back();
        }
    }
    return open.empty();
}

// A comma outside every bracket (a second declarator, or a comma expression).
bool has_top_level_comma(const std::string& text) {
    int depth = 0;
    for (char c : text) {
        if (c == '(' || c == '[' || c == '{' || c == '<') ++depth;
        if (c == ')' || c == ']' || c == '}' || c == '>') --depth;
        if (c == ',' && depth == 0) return true;
    }
    return false;
}

// Splits a trailing line comment off: code and comment (with the blanks before it).
std::pair<std::string, std::string> split_comment(const std::string& text) {
    const size_t line_start = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
    const size_t slash = text.find("//", line_start);
    if (slash == std::string::npos) return {text, ""};
    size_t code_end = slash;
    while (code_end > 0 && (text[code_end - 1] == ' ' || text[code_end - 1] == '\t')) --code_end;
    return {text.substr(0, code_end), text.substr(code_end)};
}

struct Declaration {
    std::string head;  // "const float aspect = "
    std::string init;  // the initializer, without the semicolon
};

bool as_declaration(const std::string& code, Declaration& out) {
    static const std::regex form(
        R"(^((?:(?:const|constexpr|static)\s+)*([A-Za-z_][\w:<>,]*)(?:\s*[&*])?\s+[A-Za-z_]\w*\s*=\s*)([\s\S]+);$)");
    std::smatch match;
    if (!std::regex_match(code, match, form)) return false;
    const std::string type = match[2];
    if (type == "return" || type == "case" || type == "else") return false;
    if (has_top_level_comma(match[3])) return false;
    out = {match[1], match[3]};
    return true;
}

struct BracedDeclaration {
    std::string head;  // "const Vec3 half"
    std::string type;  // "Vec3"
    std::string init;  // "{a, b, c}"
};

bool as_braced_declaration(const std::string& code, BracedDeclaration& out) {
    static const std::regex form(R"(^((?:const\s+)?([A-Za-z_][\w:<>]*)\s+[A-Za-z_]\w*)\s*(\{[\s\S]*\});$)");
    std::smatch match;
    if (!std::regex_match(code, match, form)) return false;
    out = {match[1], match[2], match[3]};
    return true;
}

bool as_labelled(const std::string& code, std::string& label, std::string& rest) {
    static const std::regex form(R"(^((?:case\s+(?:::|[^:;])+|default)\s*:\s*)([\s\S]*)$)");
    std::smatch match;
    if (!std::regex_match(code, match, form)) return false;
    label = match[1];
    rest = match[2];
    return true;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

// The last character before `at` that is not a blank or inside a line comment ('\0' at the start of the file).
char significant_before(const std::string& text, size_t at) {
    while (at > 0) {
        const char c = text[at - 1];
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
            --at;
            continue;
        }
        const size_t line_start = text.rfind('\n', at - 1) == std::string::npos ? 0 : text.rfind('\n', at - 1) + 1;
        const size_t comment = text.find("//", line_start);
        if (comment != std::string::npos && comment < at) {
            at = comment;
            continue;
        }
        return c;
    }
    return '\0';
}

}  // namespace

std::string switch_expression(int index) { return "::raster_mutant::on(" + std::to_string(index) + ")"; }

std::string switched_text(const Catalogue& catalogue, const Entry& entry, const std::string& correct,
                          const std::string& on, char before) {
    auto fail = [&](const std::string& why) {
        throw CatalogueError(where(catalogue, entry) + ": " + why +
                             "; give the entry a `schema` (its find text with MUTANT where the switch goes)");
    };
    if (!entry.schema.empty()) {
        if (entry.schema.find("MUTANT") == std::string::npos) fail("its schema has no MUTANT");
        if (correct != entry.find) fail("its schema cannot hold another entry's switch inside its find text");
        return replace_all(entry.schema, "MUTANT", "(" + on + ")");
    }
    if (!balanced(entry.find) || !balanced(entry.replace))
        fail("its find or replace text is not a whole expression or statement (brackets do not balance)");
    if (std::isalnum(static_cast<unsigned char>(before)) || before == '_' || before == '.' || before == '>')
        fail("its find text starts in the middle of a name or a member access");
    // The form follows the entry's own find text; `correct` may already hold another entry's switch.
    const auto [find_code, comment] = split_comment(entry.find);
    const std::string code = split_comment(correct).first;
    const std::string replacement = split_comment(entry.replace).first;
    const bool statement = !find_code.empty() && find_code.back() == ';';
    const bool starts_statement = before == '\0' || before == ';' || before == '{' || before == '}' ||
                                  before == ')' || before == ':';
    if (!statement || !starts_statement) {
        // An expression, or the tail of a statement that starts before the find text (`x = <find>;`).
        const auto strip = [&](const std::string& text) {
            return statement && !text.empty() && text.back() == ';' ? text.substr(0, text.size() - 1) : text;
        };
        if (replacement.empty()) fail("an expression cannot be replaced by nothing");
        return "((" + on + ") ? (" + strip(replacement) + ") : (" + strip(code) + "))" + (statement ? ";" : "") +
               comment;
    }
    Declaration wrong, right;
    if (as_declaration(find_code, right)) {
        if (!as_declaration(replacement, wrong) || wrong.head != right.head)
            fail("its find text declares a name that its replacement does not declare the same way");
        as_declaration(code, right);
        const std::string head = std::regex_replace(right.head, std::regex(R"(\bconstexpr\b)"), "const");
        return head + "(" + on + ") ? (" + wrong.init + ") : (" + right.init + ");" + comment;
    }
    BracedDeclaration braced_wrong, braced_right;
    if (as_braced_declaration(find_code, braced_right)) {
        if (!as_braced_declaration(replacement, braced_wrong) || braced_wrong.head != braced_right.head)
            fail("its find text declares a name that its replacement does not declare the same way");
        as_braced_declaration(code, braced_right);
        return braced_right.head + " = (" + on + ") ? " + braced_right.type + braced_wrong.init + " : " +
               braced_right.type + braced_right.init + ";" + comment;
    }
    std::string label, right_body = code, wrong_body = replacement;
    std::string wrong_label, find_label, find_body;
    if (as_labelled(find_code, find_label, find_body)) {
        as_labelled(code, label, right_body);
        if (!as_labelled(replacement, wrong_label, wrong_body) || wrong_label != find_label)
            fail("its find text has a case label its replacement does not keep");
    }
    if (wrong_body.empty()) return label + "if (!(" + on + ")) { " + right_body + " }" + comment;
    return label + "if (" + on + ") { " + wrong_body + " } else { " + right_body + " }" + comment;
}

std::string schemata_source(const Catalogue& catalogue, const std::string& original, const std::vector<Site>& sites,
                            const std::string& switch_header) {
    struct Region {
        size_t begin, end;
        Site site;
    };
    std::vector<Region> regions;
    for (const Site& site : sites) {
        const std::string& find = site.entry->find;
        const size_t at = original.find(find);
        if (at == std::string::npos || original.find(find, at + 1) != std::string::npos)
            throw CatalogueError(where(catalogue, *site.entry) + " is stale: its find text does not occur exactly once in " +
                                 site.entry->file);
        regions.push_back({at, at + find.size(), site});
    }
    // Outer regions first; equal regions in catalogue order.
    std::stable_sort(regions.begin(), regions.end(), [](const Region& a, const Region& b) {
        return a.begin != b.begin ? a.begin < b.begin : a.end > b.end;
    });
    // Renders [begin, end) with the regions in [first, last) (all inside it) switched in.
    auto render = [&](auto&& self, size_t begin, size_t end, size_t first, size_t last) -> std::string {
        std::string out;
        size_t cursor = begin;
        for (size_t i = first; i < last;) {
            const Region& region = regions[i];
            if (region.begin < cursor)
                throw CatalogueError(where(catalogue, *region.site.entry) + " overlaps another entry's find text in " +
                                     region.site.entry->file + " without lying inside it");
            size_t same = i + 1;
            while (same < last && regions[same].begin == region.begin && regions[same].end == region.end) ++same;
            size_t inner = same;
            while (inner < last && regions[inner].begin < region.end) {
                if (regions[inner].end > region.end)
                    throw CatalogueError(where(catalogue, *regions[inner].site.entry) + " overlaps [" +
                                         region.site.entry->name + "]'s find text without lying inside it");
                ++inner;
            }
            out += original.substr(cursor, region.begin - cursor);
            std::string text = self(self, region.begin, region.end, same, inner);
            for (size_t k = i; k < same; ++k)
                text = switched_text(catalogue, *regions[k].site.entry, text, switch_expression(regions[k].site.index),
                                     significant_before(original, region.begin));
            out += text;
            cursor = region.end;
            i = inner;
        }
        return out + original.substr(cursor, end - cursor);
    };
    const std::string body = render(render, 0, original.size(), 0, regions.size());
    return "#include \"" + switch_header + "\"  // mutant schemata: generated from mutants/bugs.txt\n" + body;
}

}  // namespace raster::mutants
