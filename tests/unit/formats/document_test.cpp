// Document tests: the tree and its positions from both parsers, the nesting limit, aliases, nulls, empty documents,
// repeated keys, and JSON syntax errors located from the bytes nlohmann read.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "raster/core/errors.h"
#include "raster/formats/document.h"

namespace {

using raster::Document;
using raster::InputError;
using raster::Node;
using raster::parse_document;

// Every node in document order (a map's key before its value), as "kind 'text' line:column".
void describe(const Node& node, std::vector<std::string>& out) {
    static const char* const kinds[] = {"undefined", "null", "scalar", "sequence", "map"};
    std::string line = kinds[static_cast<int>(node.kind())];
    if (node.is_scalar()) line += " '" + node.text() + "'";
    out.push_back(line + " " + std::to_string(node.line()) + ":" + std::to_string(node.column()));
    for (const Node& item : node.items()) describe(item, out);
    for (const Node::Entry& entry : node.entries()) {
        describe(entry.key, out);
        describe(entry.value, out);
    }
}

std::vector<std::string> described(std::string_view text) {
    const Document document = parse_document(text, "doc");
    std::vector<std::string> out;
    describe(document.root(), out);
    return out;
}

// The same bytes from line 2 on, read by each parser: a blank first line leaves the text JSON-looking, a comment
// line makes it YAML (whose flow style is a superset of this JSON).
std::string as_json(const std::string& text) { return "\n" + text; }
std::string as_yaml(const std::string& text) { return "#\n" + text; }

// The error parse_document throws for `text`.
InputError error_for(std::string_view text) {
    try {
        parse_document(text, "doc");
    } catch (const InputError& error) {
        return error;
    }
    ADD_FAILURE() << "no InputError";
    return InputError("doc", -1, -1, "");
}

// ---------------------------------------------------------------------------------------------------------------
// Positions: each node where its first character is, 1-based, the same from yaml-cpp's marks and from the bytes
// nlohmann's lexer has read

// A tab at the start of line 6; numbers before ',', ']', a line break and a space; strings holding separators.
const std::string kEveryToken = "{\"name\": \"a\\\"b\\u00e9\", \"sep\": \"a, b: ]\",\n"
                                " \"count\": 12\n"
                                " , \"negative\": -3,\n"
                                " \"scale\": [1.5e3, -0.25, 0],\n"
                                "\t\"flags\": [true, false, null],\n"
                                " \"empty\": [], \"none\": {},\n"
                                " \"nested\": {\"deep\": [[1]]}}\n";
const std::vector<std::string> kEveryTokenNodes = {
    "map 2:1",
    "scalar 'name' 2:2", "scalar 'a\"b\xc3\xa9' 2:10",
    "scalar 'sep' 2:24", "scalar 'a, b: ]' 2:31",
    "scalar 'count' 3:2", "scalar '12' 3:11",
    "scalar 'negative' 4:4", "scalar '-3' 4:16",
    "scalar 'scale' 5:2", "sequence 5:11", "scalar '1.5e3' 5:12", "scalar '-0.25' 5:19", "scalar '0' 5:26",
    "scalar 'flags' 6:2", "sequence 6:11", "scalar 'true' 6:12", "scalar 'false' 6:18", "null 6:25",
    "scalar 'empty' 7:2", "sequence 7:11",
    "scalar 'none' 7:15", "map 7:23",
    "scalar 'nested' 8:2", "map 8:12", "scalar 'deep' 8:13", "sequence 8:21", "sequence 8:22", "scalar '1' 8:23",
};

TEST(Document, jsonNodesAreWhereYamlCppPutsThem) {
    EXPECT_EQ(described(as_json(kEveryToken)), kEveryTokenNodes);
    EXPECT_EQ(described(as_yaml(kEveryToken)), kEveryTokenNodes);
}

TEST(Document, lineBreaksOfTwoBytesMoveNoNode) {
    std::string crlf;
    for (const char c : kEveryToken) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    EXPECT_EQ(described(as_json(crlf)), kEveryTokenNodes);
    EXPECT_EQ(described(as_yaml(crlf)), kEveryTokenNodes);
}

TEST(Document, everyKindOfJsonNumberKeepsItsText) {
    // Signed, unsigned, too large for 64 bits (nlohmann's three number events), with no space before ',' or ']'.
    const std::string numbers = "[0,-0,1.5,-1.5e-3,1E+2,12345678901234567890,123456789012345678901234]";
    const std::vector<std::string> nodes = {
        "sequence 2:1", "scalar '0' 2:2", "scalar '-0' 2:4", "scalar '1.5' 2:7", "scalar '-1.5e-3' 2:11",
        "scalar '1E+2' 2:19", "scalar '12345678901234567890' 2:24", "scalar '123456789012345678901234' 2:45",
    };
    EXPECT_EQ(described(as_json(numbers)), nodes);
    EXPECT_EQ(described(as_yaml(numbers)), nodes);
}

TEST(Document, yamlBlockNodesAreAtTheirFirstCharacter) {
    // A block map is where its first key is; a node with an anchor is where the anchor is.
    const std::string text = "scene:\n"
                             "  name: plain text\n"
                             "  list:\n"
                             "    - 1\n"
                             "    - \"two\"\n"
                             "    - 'it''s'\n"
                             "  literal: |\n"
                             "    two\n"
                             "    lines\n"
                             "  anchored: &a [x, y]\n";
    const std::vector<std::string> nodes = {
        "map 1:1", "scalar 'scene' 1:1", "map 2:3",
        "scalar 'name' 2:3", "scalar 'plain text' 2:9",
        "scalar 'list' 3:3", "sequence 4:5", "scalar '1' 4:7", "scalar 'two' 5:7", "scalar 'it's' 6:7",
        "scalar 'literal' 7:3", "scalar 'two\nlines\n' 7:12",
        "scalar 'anchored' 10:3", "sequence 10:13", "scalar 'x' 10:17", "scalar 'y' 10:20",
    };
    EXPECT_EQ(described(text), nodes);
}

TEST(Document, bothParsersAgreeOnTheCorpusJsonScenes) {
    // Every hand-written JSON scene of the corpus, read by each parser: the same tree, or the same nesting error.
    int compared = 0;
    for (const char* folder : {"corpus/seeds/001", "corpus/seeds/003", "corpus/fuzz/scene_seed001",
                               "corpus/fuzz/scene_seed003"}) {
        const std::filesystem::path path = std::filesystem::path(RASTER_SOURCE_DIR) / folder;
        for (const auto& entry : std::filesystem::directory_iterator(path)) {
            if (entry.path().extension() != ".json") continue;
            std::ostringstream bytes;
            bytes << std::ifstream(entry.path(), std::ios::binary).rdbuf();
            const std::string text = bytes.str();
            try {
                const std::vector<std::string> json = described(as_json(text));
                EXPECT_EQ(described(as_yaml(text)), json) << entry.path();
                ++compared;
            } catch (const InputError& json_error) {
                if (json_error.message().find("nesting") == std::string::npos) continue;  // a syntax error on purpose
                const InputError yaml_error = error_for(as_yaml(text));
                EXPECT_EQ(yaml_error.message(), json_error.message()) << entry.path();
                EXPECT_EQ(yaml_error.line(), json_error.line()) << entry.path();
                EXPECT_EQ(yaml_error.column(), json_error.column()) << entry.path();
            }
        }
    }
    EXPECT_GE(compared, 16);  // all but syntax_error.json and deep.json, today
}

// ---------------------------------------------------------------------------------------------------------------
// The nesting limit: 64 levels read, the 65th opening refused where it is

std::string flow(int levels) { return std::string(levels, '[') + std::string(levels, ']'); }
std::string block_sequences(int levels) {
    std::string text;
    for (int i = 0; i < levels; ++i) text += "- ";
    return text + "x\n";
}
std::string block_maps(int levels) {
    std::string text;
    for (int i = 0; i < levels; ++i) text += std::string(2 * i, ' ') + "a:\n";
    return text;
}

void expect_nesting_refused_at(std::string_view text, int line, int column) {
    const InputError error = error_for(text);
    EXPECT_EQ(error.message(), "nesting deeper than 64 levels");
    EXPECT_EQ(error.line(), line);
    EXPECT_EQ(error.column(), column);
}

TEST(Document, nestingOf64LevelsIsRead) {
    EXPECT_NO_THROW(parse_document(flow(64), "doc"));            // JSON
    EXPECT_NO_THROW(parse_document("#\n" + flow(64), "doc"));    // YAML flow
    EXPECT_NO_THROW(parse_document(block_sequences(64), "doc"));  // YAML block sequences
    EXPECT_NO_THROW(parse_document(block_maps(64), "doc"));       // YAML block maps
    std::string objects;
    for (int i = 0; i < 64; ++i) objects += "{\"a\": ";
    EXPECT_NO_THROW(parse_document(objects + "1" + std::string(64, '}'), "doc"));
}

TEST(Document, the65thOpeningIsRefused) {
    expect_nesting_refused_at(flow(65), 1, 65);
    expect_nesting_refused_at("#\n" + flow(65), 2, 65);
    expect_nesting_refused_at(block_sequences(65), 1, 129);  // the 65th "- "
    expect_nesting_refused_at(block_maps(65), 65, 129);      // the 65th map, at its key
    std::string objects;
    for (int i = 0; i < 65; ++i) objects += "{\"a\": ";
    expect_nesting_refused_at(objects + "1" + std::string(65, '}'), 1, 6 * 64 + 1);
    // Deep input is refused when its 65th level opens, without reading (or recursing into) the rest.
    expect_nesting_refused_at(flow(100000), 1, 65);
    expect_nesting_refused_at(block_sequences(100000), 1, 129);
    // So is deep flow nesting inside a YAML document, which yaml-cpp's scanner would read to its end (a token for
    // every bracket) before any event: a million of them, refused at the 65th, behind a word with an apostrophe
    // (which does not open a quoted scalar) and after a quoted string holding brackets (which do not count).
    expect_nesting_refused_at("name: it's \"[[[[\"\nmeshes: " + flow(1000000), 2, 8 + 65);
}

TEST(Document, flowAndBlockNestingAreCountedApart) {
    // 64 block sequences, and 64 flow levels inside the last.
    EXPECT_NO_THROW(parse_document(block_sequences(64).substr(0, 128) + flow(64) + "\n", "doc"));
    expect_nesting_refused_at(block_sequences(64).substr(0, 128) + flow(65) + "\n", 1, 129 + 64);
}

TEST(Document, bracketsInStringsAndCommentsAreNoNesting) {
    EXPECT_NO_THROW(parse_document("# " + flow(65) + "\na: '" + flow(65) + "'\nb: \"" + flow(65) + "\"\n", "doc"));
    EXPECT_NO_THROW(parse_document("[\"" + flow(65) + "\"]", "doc"));
}

// ---------------------------------------------------------------------------------------------------------------
// What a node is: aliases, nulls, empty documents, repeated keys

TEST(Document, anAliasIsTheNodeItNames) {
    const Document document = parse_document("first: &a {x: 1}\nsecond: *a\n", "doc");
    const Node& root = document.root();
    ASSERT_EQ(root.size(), 2u);
    EXPECT_EQ(&root.entries()[1].value, &root.entries()[0].value);
    EXPECT_EQ(root.entries()[1].value.line(), 1);
    EXPECT_EQ(root.entries()[1].value.column(), 8);
    // An alias inside the node it names makes a loop, not a copy.
    const Document loop = parse_document("&a [*a]\n", "doc");
    ASSERT_EQ(loop.root().size(), 1u);
    EXPECT_EQ(&loop.root()[0], &loop.root());
}

TEST(Document, plainNullsAreNullNodesAndQuotedOnesAreText) {
    const Document yaml = parse_document(as_yaml("[~, null, Null, NULL, 'null', \"~\", nil]\n"), "doc");
    ASSERT_EQ(yaml.root().size(), 7u);
    for (size_t i = 0; i < 4; ++i) EXPECT_TRUE(yaml.root()[i].is_null()) << i;
    for (size_t i = 4; i < 7; ++i) EXPECT_TRUE(yaml.root()[i].is_scalar()) << i;
    EXPECT_EQ(yaml.root()[4].text(), "null");
    const Document nothing = parse_document("a:\nb: 1\n", "doc");
    EXPECT_TRUE(nothing.root().entries()[0].value.is_null());
    const Document json = parse_document("[null, \"null\"]", "doc");
    EXPECT_TRUE(json.root()[0].is_null());
    EXPECT_EQ(json.root()[1].text(), "null");
}

TEST(Document, anEmptyDocumentIsANullRootLocatedNowhere) {
    for (const char* text : {"", "\n\n  \n", "# only a comment\n"}) {
        const Document document = parse_document(text, "doc");
        EXPECT_TRUE(document.root().is_null()) << text;
        EXPECT_EQ(document.root().line(), 0) << text;
        EXPECT_EQ(document.root().column(), 0) << text;
    }
    EXPECT_TRUE(parse_document("---\n", "doc").root().is_null());
    // Only the first YAML document is read.
    EXPECT_EQ(parse_document("a: 1\n---\n[unclosed\n", "doc").root().size(), 1u);
}

TEST(Document, repeatedKeysAreKeptInFileOrder) {
    const std::vector<std::string> nodes = {"map 1:1",         "scalar 'a' 1:2",  "scalar '1' 1:7",
                                            "scalar 'b' 1:10", "scalar '2' 1:15", "scalar 'a' 1:18",
                                            "scalar '3' 1:23"};
    EXPECT_EQ(described("{\"a\": 1, \"b\": 2, \"a\": 3}"), nodes);
    EXPECT_EQ(described("{\"a\": 1, \"b\": 2, \"a\": 3}\n"), nodes);
    EXPECT_EQ(described("a: 1\nb: 2\na: 3\n"),
              (std::vector<std::string>{"map 1:1", "scalar 'a' 1:1", "scalar '1' 1:4", "scalar 'b' 2:1",
                                        "scalar '2' 2:4", "scalar 'a' 3:1", "scalar '3' 3:4"}));
}

TEST(Document, anAbsentKeyIsTheUndefinedNode) {
    const Node& undefined = Node::undefined();
    EXPECT_FALSE(undefined.is_defined());
    EXPECT_EQ(undefined.line(), 0);
    EXPECT_EQ(undefined.column(), 0);
    EXPECT_EQ(undefined.size(), 0u);
}

// ---------------------------------------------------------------------------------------------------------------
// JSON syntax errors: strict JSON, located by the count of bytes read, in nlohmann's words without its prefix

void expect_json_error_at(std::string_view text, int line, int column, const std::string& message) {
    const InputError error = error_for(text);
    EXPECT_EQ(error.line(), line) << error.what();
    EXPECT_EQ(error.column(), column) << error.what();
    EXPECT_EQ(error.message().substr(0, message.size()), message) << error.what();
    EXPECT_EQ(error.message().find("json.exception"), std::string::npos) << error.what();
    EXPECT_EQ(error.message().find("line "), std::string::npos) << error.what();
}

TEST(Document, jsonSyntaxErrorsAreLocatedAtTheLastByteRead) {
    expect_json_error_at("{\n  \"a\": [\n    1,,\n", 3, 7,
                         "JSON syntax error: syntax error while parsing value - unexpected ','; expected '[', '{', or "
                         "a literal");
    // A number is over when the lexer has read the character after it; the error is at the number's last digit,
    // also when that character is a line break.
    expect_json_error_at("[1 22\n]", 1, 5, "JSON syntax error: syntax error while parsing array - unexpected number");
    // At the end of the text, the column is one past the last byte.
    expect_json_error_at("{\"a\": 1", 1, 8, "JSON syntax error: syntax error while parsing object - unexpected end");
    // A line break that ends the error counts into the next line, at column 0, as nlohmann counts it.
    expect_json_error_at("{\"a\": \"abc\n\"}", 2, 0, "JSON syntax error: syntax error while parsing value - invalid "
                                                      "string: control character U+000A (LF)");
    expect_json_error_at("[1e999]", 1, 6, "JSON syntax error: number overflow parsing '1e999'");
    expect_json_error_at(std::string("[1]\0 [2]", 8), 1, 4, "JSON syntax error: unexpected NUL character (U+0000)");
}

TEST(Document, jsonIsStrict) {
    expect_json_error_at("[1, 2,]", 1, 7, "JSON syntax error: syntax error while parsing value - unexpected ']'");
    expect_json_error_at("[1] // no comments", 1, 5, "JSON syntax error: syntax error while parsing value - invalid");
    expect_json_error_at("['single']", 1, 2, "JSON syntax error: syntax error while parsing value - invalid literal");
    expect_json_error_at("{\"a\": 1} {}", 1, 10,
                         "JSON syntax error: syntax error while parsing value - unexpected '{'; expected end of input");
}

}  // namespace
