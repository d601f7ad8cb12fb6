// Scene documents: yaml-cpp's events or nlohmann's SAX events build one located tree, with the nesting limit
// counted as collections open.
#include "raster/formats/document.h"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include "raster/core/errors.h"

namespace raster {

const Node& Node::undefined() {
    static const Node node(Kind::undefined, 0, 0);
    return node;
}

// Adds each node where the parser's events put it: the root, the next item of the open sequence, or the key and
// then the value of an entry of the open map.
class DocumentBuilder {
public:
    explicit DocumentBuilder(const std::string& file) : file_(file) {}

    const Node& leaf(Node::Kind kind, std::string text, int line, int column) {
        Node& node = document_.nodes_.emplace_back(kind, line, column);
        node.text_ = std::move(text);
        attach(node);
        return node;
    }

    // A node already built, again: what an alias names.
    void repeat(const Node& node) { attach(node); }

    // Opens a sequence or map. Flow collections ([ ] and { }, and all inside them) and block collections are
    // counted apart, each kind refused past kMaxDocumentNesting levels, before the parser recurses into it.
    const Node& open(Node::Kind kind, int line, int column, bool flow) {
        flow = flow || (!open_.empty() && open_.back().flow);
        if (++(flow ? flow_depth_ : block_depth_) > kMaxDocumentNesting)
            throw InputError(file_, line, column,
                             "nesting deeper than " + std::to_string(kMaxDocumentNesting) + " levels");
        Node& node = document_.nodes_.emplace_back(kind, line, column);
        attach(node);
        open_.push_back({&node, flow, nullptr});
        return node;
    }

    void close() {
        --(open_.back().flow ? flow_depth_ : block_depth_);
        open_.pop_back();
    }

    // The document built; with no node at all (an empty YAML stream), a null root located nowhere.
    Document finish() {
        if (!document_.root_->is_defined()) document_.root_ = &document_.nodes_.emplace_back(Node::Kind::null, 0, 0);
        return std::move(document_);
    }

private:
    struct OpenCollection {
        Node* node;
        bool flow;
        const Node* key;  // a map's key waiting for its value
    };

    void attach(const Node& node) {
        if (open_.empty()) {
            if (!document_.root_->is_defined()) document_.root_ = &node;
            return;
        }
        OpenCollection& parent = open_.back();
        if (parent.node->is_sequence()) {
            parent.node->items_.push_back(node);
        } else if (!parent.key) {
            parent.key = &node;
        } else {
            parent.node->entries_.push_back({*parent.key, node});
            parent.key = nullptr;
        }
    }

    const std::string& file_;
    Document document_;
    std::vector<OpenCollection> open_;
    int flow_depth_ = 0;
    int block_depth_ = 0;
};

namespace {

// ---- YAML: yaml-cpp's events ----

int line_of(const YAML::Mark& mark) { return mark.line >= 0 ? mark.line + 1 : 0; }
int column_of(const YAML::Mark& mark) { return mark.column >= 0 ? mark.column + 1 : 0; }

// Each event becomes a node at the event's mark (what yaml-cpp's own nodes were given). Tags are not kept: a
// scalar is its text whatever its tag, as the readers always took it.
class YamlEvents : public YAML::EventHandler {
public:
    explicit YamlEvents(DocumentBuilder& builder) : builder_(builder) {}

    void OnDocumentStart(const YAML::Mark&) override {}
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
        remember(anchor, builder_.leaf(Node::Kind::null, "", line_of(mark), column_of(mark)));
    }
    void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
        // yaml-cpp numbers anchors from 1 in the order their nodes arrive, and refuses an alias it has no anchor for.
        if (anchor == 0 || anchor >= anchors_.size() || !anchors_[anchor])
            throw YAML::ParserException(mark, YAML::ErrorMsg::UNKNOWN_ANCHOR);
        builder_.repeat(*anchors_[anchor]);
    }
    void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  const std::string& value) override {
        remember(anchor, builder_.leaf(Node::Kind::scalar, value, line_of(mark), column_of(mark)));
    }
    void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                         YAML::EmitterStyle::value style) override {
        remember(anchor, builder_.open(Node::Kind::sequence, line_of(mark), column_of(mark),
                                       style == YAML::EmitterStyle::Flow));
    }
    void OnSequenceEnd() override { builder_.close(); }
    void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                    YAML::EmitterStyle::value style) override {
        remember(anchor,
                 builder_.open(Node::Kind::map, line_of(mark), column_of(mark), style == YAML::EmitterStyle::Flow));
    }
    void OnMapEnd() override { builder_.close(); }

private:
    void remember(YAML::anchor_t anchor, const Node& node) {
        if (anchor == 0) return;
        if (anchors_.size() <= anchor) anchors_.resize(anchor + 1, nullptr);
        anchors_[anchor] = &node;
    }

    DocumentBuilder& builder_;
    std::vector<const Node*> anchors_;
};

// yaml-cpp's scanner reads a flow collection to its end before it emits the collection's first event (it must know
// whether the collection is a key), keeping a token of some 200 bytes for every bracket on the way: a file of a
// million nested `[` takes gigabytes before the event handler's count could refuse it. So flow nesting is counted
// first, in one pass over the text that skips quoted strings and comments and counts every other bracket (one in a
// plain scalar too, which only makes it stricter), and refused at its 65th level, at that bracket.
void refuse_deep_flow_nesting(std::string_view text, const std::string& file) {
    int depth = 0, line = 1;
    size_t line_start = 0;
    char quote = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') {
            ++line;
            line_start = i + 1;
        }
        if (quote) {
            if (c == '\\' && quote == '"' && i + 1 < text.size() && text[i + 1] != '\n') ++i;
            else if (c == quote) quote = 0;
            continue;
        }
        // A quote opens a quoted scalar only where a token can start (an apostrophe inside a plain word does not).
        const bool token_start = i == 0 || std::string_view(" \t\r\n[{,:-?").find(text[i - 1]) != std::string_view::npos;
        if ((c == '"' || c == '\'') && token_start) {
            quote = c;
        } else if (c == '#' && (i == 0 || text[i - 1] == ' ' || text[i - 1] == '\t' || text[i - 1] == '\n')) {
            while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxDocumentNesting)
                throw InputError(file, line, static_cast<int>(i - line_start) + 1,
                                 "nesting deeper than " + std::to_string(kMaxDocumentNesting) + " levels");
        } else if (c == ']' || c == '}') {
            depth = std::max(0, depth - 1);
        }
    }
}

Document parse_yaml(std::string_view text, const std::string& file) {
    refuse_deep_flow_nesting(text, file);
    DocumentBuilder builder(file);
    YamlEvents events(builder);
    std::istringstream stream{std::string(text)};
    try {
        YAML::Parser parser(stream);
        parser.HandleNextDocument(events);  // the first document only, as YAML::Load reads
    } catch (const YAML::Exception& e) {
        throw InputError(file, line_of(e.mark), column_of(e.mark), "YAML syntax error: " + e.msg);
    }
    return builder.finish();
}

// ---- JSON: nlohmann's SAX events ----

// Line and column in `text` the way yaml-cpp counts them: a line ends at '\n', a column is a byte.
class TextLocator {
public:
    explicit TextLocator(std::string_view text) : text_(text) {}

    // Counts the line breaks in the first `length` bytes: line() is the line they end on, line_start() where that
    // line begins. The parse only moves forward; asked for an earlier place, it counts again from the start.
    void advance_to(size_t length) {
        length = std::min(length, text_.size());
        if (length < scanned_) scanned_ = 0, line_ = 1, line_start_ = 0;
        for (; scanned_ < length; ++scanned_)
            if (text_[scanned_] == '\n') ++line_, line_start_ = scanned_ + 1;
    }
    int line() const { return line_; }
    size_t line_start() const { return line_start_; }

private:
    std::string_view text_;
    size_t scanned_ = 0;
    int line_ = 1;
    size_t line_start_ = 0;
};

// The text as a character range that counts what nlohmann's lexer reads: each character it takes, and each time
// it finds the end (it compares with the end before every read, and reads past the last byte only at the end).
struct ReadCount {
    size_t characters = 0;
    bool end_reached = false;
};

class CountingIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    CountingIterator(const char* position, ReadCount* count) : position_(position), count_(count) {}

    reference operator*() const { return *position_; }
    CountingIterator& operator++() {
        ++position_;
        ++count_->characters;
        return *this;
    }
    bool operator==(const CountingIterator& other) const {
        const bool equal = position_ == other.position_;
        count_->end_reached = count_->end_reached || equal;
        return equal;
    }

private:
    const char* position_;
    ReadCount* count_;
};

// Each event's token is located in the text: it starts at the first byte after the previous token that is not
// white space or a separator (',' or ':', which nlohmann has checked by then), and ends where the lexer has read
// to when the event arrives, but for a number, whose end the lexer learns by reading one character past it.
class JsonEvents : public nlohmann::json_sax<nlohmann::json> {
public:
    JsonEvents(std::string_view text, const ReadCount& read, DocumentBuilder& builder, const std::string& file)
        : text_(text), read_(read), builder_(builder), file_(file), locator_(text) {}

    bool null() override { return leaf(Node::Kind::null, ""); }
    bool boolean(bool) override { return as_written(read_.characters); }
    bool number_integer(number_integer_t) override { return as_written(number_end()); }
    bool number_unsigned(number_unsigned_t) override { return as_written(number_end()); }
    bool number_float(number_float_t, const string_t&) override { return as_written(number_end()); }
    bool string(string_t& value) override { return leaf(Node::Kind::scalar, value); }
    bool key(string_t& value) override { return leaf(Node::Kind::scalar, value); }
    bool binary(binary_t&) override { return false; }  // JSON text has no binary values
    bool start_object(std::size_t) override { return open(Node::Kind::map); }
    bool start_array(std::size_t) override { return open(Node::Kind::sequence); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& error) override {
        // A number too large for a double arrives as out_of_range, which carries no byte: `position` is the same count.
        const auto* syntax = dynamic_cast<const nlohmann::json::parse_error*>(&error);
        fail(syntax ? syntax->byte : position, problem(error.what()));
    }

    // A syntax error found when the lexer has read `read` characters, located at the last of them. nlohmann counts
    // a line break it stops at into the next line, at column 0, and so do these messages.
    [[noreturn]] void fail(size_t read, const std::string& problem) {
        locator_.advance_to(read);
        const int column = static_cast<int>(read - std::min(read, locator_.line_start()));
        throw InputError(file_, locator_.line(), column, "JSON syntax error: " + problem);
    }

private:
    // nlohmann's message without its name ("[json.exception.parse_error.101] ") and, for a parse error, without
    // "parse error at line 3, column 7: ": InputError gives the position.
    static std::string problem(std::string what) {
        if (const size_t name_end = what.find("] "); name_end != std::string::npos) what.erase(0, name_end + 2);
        if (what.rfind("parse error", 0) == 0)
            if (const size_t position_end = what.find(": "); position_end != std::string::npos)
                what.erase(0, position_end + 2);
        return what;
    }

    size_t token_start() const {
        const size_t start = text_.find_first_not_of(" \t\r\n,:", cursor_);
        return start == std::string_view::npos ? text_.size() : start;
    }

    // A number's last byte: the lexer has read one character past it, unless the text ended there.
    size_t number_end() const { return read_.characters - (read_.end_reached ? 0 : 1); }

    // Locates the token that starts at `start` and ends `end` bytes in, and moves past it.
    std::pair<int, int> locate(size_t start, size_t end) {
        locator_.advance_to(start);
        cursor_ = end;
        return {locator_.line(), static_cast<int>(start - locator_.line_start()) + 1};
    }

    bool leaf(Node::Kind kind, std::string text) {
        const auto [line, column] = locate(token_start(), read_.characters);
        builder_.leaf(kind, std::move(text), line, column);
        return true;
    }

    // A scalar whose text is the token as written: a number or a boolean, as yaml-cpp read them.
    bool as_written(size_t end) {
        const size_t start = token_start();
        const auto [line, column] = locate(start, end);
        builder_.leaf(Node::Kind::scalar, std::string(text_.substr(start, end - start)), line, column);
        return true;
    }

    bool open(Node::Kind kind) {
        const auto [line, column] = locate(token_start(), read_.characters);
        builder_.open(kind, line, column, true);
        return true;
    }

    bool close() {
        cursor_ = read_.characters;
        builder_.close();
        return true;
    }

    std::string_view text_;
    const ReadCount& read_;
    DocumentBuilder& builder_;
    const std::string& file_;
    TextLocator locator_;
    size_t cursor_ = 0;  // where the last token located ends
};

Document parse_json(std::string_view text, const std::string& file) {
    DocumentBuilder builder(file);
    ReadCount read;
    JsonEvents events(text, read, builder, file);
    // Strict JSON: no comments, no trailing commas, nothing after the value.
    nlohmann::json::sax_parse(CountingIterator(text.data(), &read), CountingIterator(text.data() + text.size(), &read),
                              &events, nlohmann::json::input_format_t::json, true, false);
    // nlohmann's lexer takes a NUL character for the end of the input, so text after one is not read at all.
    if (!read.end_reached) events.fail(read.characters, "unexpected NUL character (U+0000) after the value");
    return builder.finish();
}

}  // namespace

Document parse_document(std::string_view text, const std::string& file) {
    const size_t first = text.find_first_not_of(" \t\r\n");
    if (first != std::string_view::npos && (text[first] == '{' || text[first] == '['))
        return parse_json(text, file);
    return parse_yaml(text, file);
}

}  // namespace raster
