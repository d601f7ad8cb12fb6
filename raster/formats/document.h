// Scene documents: the tree one parse of a YAML or JSON file gives, every node located at its line and column.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace raster {

class DocumentBuilder;

// Nesting deeper than this many flow collections ([ and {), or this many block collections, is refused while
// parsing: the parsers recurse once per level.
inline constexpr int kMaxDocumentNesting = 64;

// Largest scene file (a document) read, in bytes.
inline constexpr uint64_t kMaxSceneFileBytes = uint64_t{256} << 20;

// One node of a parsed document. A map keeps its entries in file order, a repeated key included; an alias is the
// very node it names. Nodes live in their Document and are only handled by reference.
class Node {
public:
    enum class Kind {
        undefined,  // what a lookup finds for a key a map does not have
        null,       // `null`, `~` or nothing, written plain
        scalar,     // any other value, as its text: numbers and booleans are read from it
        sequence,
        map,
    };
    struct Entry {
        const Node& key;
        const Node& value;
    };

    Node(Kind kind, int line, int column) : kind_(kind), line_(line), column_(column) {}
    Node(const Node&) = delete;
    Node& operator=(const Node&) = delete;

    // The node that stands for an absent value, located nowhere (line and column 0).
    static const Node& undefined();

    Kind kind() const { return kind_; }
    bool is_defined() const { return kind_ != Kind::undefined; }
    bool is_null() const { return kind_ == Kind::null; }
    bool is_scalar() const { return kind_ == Kind::scalar; }
    bool is_sequence() const { return kind_ == Kind::sequence; }
    bool is_map() const { return kind_ == Kind::map; }

    // 1-based, where the node's first character is (for a block map, its first key); 0 when undefined.
    int line() const { return line_; }
    int column() const { return column_; }

    // A scalar's text (quotes and escapes resolved); empty for every other kind.
    const std::string& text() const { return text_; }
    // A sequence's items or a map's entries; 0 for every other kind.
    size_t size() const { return kind_ == Kind::map ? entries_.size() : items_.size(); }
    const std::vector<std::reference_wrapper<const Node>>& items() const { return items_; }
    const Node& operator[](size_t index) const { return items_.at(index); }
    const std::vector<Entry>& entries() const { return entries_; }

private:
    friend class DocumentBuilder;

    Kind kind_;
    int line_;
    int column_;
    std::string text_;
    std::vector<std::reference_wrapper<const Node>> items_;
    std::vector<Entry> entries_;
};

// A parsed file: its nodes and the root among them. Moving a Document keeps every Node where it is.
class Document {
public:
    const Node& root() const { return *root_; }

private:
    friend class DocumentBuilder;

    std::deque<Node> nodes_;
    const Node* root_ = &Node::undefined();
};

// Parses text in one pass: JSON-looking text (its first non-blank character '{' or '[') by a strict JSON parser,
// everything else as YAML 1.2. Only the first YAML document is read; an empty one is a null root. Throws
// InputError naming `file` at the exact line and column of a syntax error or of the opening that nests too deep.
Document parse_document(std::string_view text, const std::string& file);

}  // namespace raster
