// The catalogue reader: escapes decoded, and every malformed line named by file and line.
#include "mutants/catalogue.h"

#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"

namespace raster::mutants {
namespace {

using test_support::TempDir;

const std::string kEntry =
    "[one]\nbug = b\nfamily = setup\nfile = raster/x.cpp\nfind = a\\sb\\nc\nreplace =\nscene = s.yaml\nflags =\n";

std::string error_of(const std::string& text) {
    TempDir dir;
    try {
        read_catalogue(dir.write("bugs.txt", text));
    } catch (const CatalogueError& error) {
        return error.what();
    }
    return "";
}

TEST(Catalogue, readsEntriesAndDecodesEscapes) {
    TempDir dir;
    const Catalogue catalogue = read_catalogue(dir.write("bugs.txt", "# comment\n\n" + kEntry));
    ASSERT_EQ(catalogue.entries.size(), 1u);
    const Entry& entry = catalogue.entries[0];
    EXPECT_EQ(entry.name, "one");
    EXPECT_EQ(entry.line, 3);
    EXPECT_EQ(entry.find, "a b\nc");
    EXPECT_EQ(entry.replace, "");
    EXPECT_EQ(entry.schema, "");
    EXPECT_EQ(catalogue.find("one"), &entry);
    EXPECT_EQ(catalogue.find("two"), nullptr);
}

TEST(Catalogue, namesTheLineOfEachMistake) {
    EXPECT_NE(error_of(kEntry + "colour = red\n").find("bugs.txt:9: unknown key 'colour'"), std::string::npos);
    EXPECT_NE(error_of(kEntry + "\n" + kEntry).find("bugs.txt:10: entry [one] appears twice"), std::string::npos);
    EXPECT_NE(error_of(kEntry + "bug = again\n").find("bugs.txt:9: [one] sets 'bug' twice"), std::string::npos);
    EXPECT_NE(error_of("bug = x\n").find("bugs.txt:1: 'bug' before the first [name]"), std::string::npos);
    EXPECT_NE(error_of("[one]\nfind = \\q\n").find("bugs.txt:2: [one] find: unknown escape"), std::string::npos);
    EXPECT_NE(error_of("[one]\nbug = b\n").find("bugs.txt:1: [one] has no 'family'"), std::string::npos);
    std::string oracle = kEntry;
    oracle.replace(oracle.find("raster/x.cpp"), 12, "oracle/x.cpp");
    EXPECT_NE(error_of(oracle).find("bugs belong in the production path"), std::string::npos);
    EXPECT_NE(error_of("").find("no entries"), std::string::npos);
}

}  // namespace
}  // namespace raster::mutants
