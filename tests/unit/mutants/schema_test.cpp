// Mutant schemata: the switch each form of find text becomes, nested and shared regions, and what is refused.
#include "mutants/schema.h"

#include <gtest/gtest.h>

namespace raster::mutants {
namespace {

Entry entry(const std::string& name, const std::string& find, const std::string& replace,
            const std::string& schema = "") {
    Entry e;
    e.name = name;
    e.line = 1;
    e.file = "raster/x.cpp";
    e.find = find;
    e.replace = replace;
    e.schema = schema;
    return e;
}

std::string switched(const Entry& e) { return switched_text(Catalogue{"bugs.txt", {e}}, e, e.find, "ON"); }

TEST(Schema, aDeclarationChoosesItsInitializer) {
    EXPECT_EQ(switched(entry("d", "const double t = a / b;  // why", "const double t = b / a;")),
              "const double t = (ON) ? (b / a) : (a / b);  // why");
    // constexpr cannot hold a runtime switch
    EXPECT_EQ(switched(entry("c", "constexpr double k = -1.0;", "constexpr double k = 1.0;")),
              "const double k = (ON) ? (1.0) : (-1.0);");
}

TEST(Schema, aStatementBranches) {
    EXPECT_EQ(switched(entry("s", "x = f(y);", "x = g(y);")), "if (ON) { x = g(y); } else { x = f(y); }");
    EXPECT_EQ(switched(entry("e", "check(a);", "")), "if (!(ON)) { check(a); }");
    EXPECT_EQ(switched(entry("l", "case kNear: return w - n;", "case kNear: return w;")),
              "case kNear: if (ON) { return w; } else { return w - n; }");
}

TEST(Schema, anExpressionChoosesItsValue) {
    EXPECT_EQ(switched(entry("x", "(1.0 - y) * h", "(y + 1.0) * h")), "((ON) ? ((y + 1.0) * h) : ((1.0 - y) * h))");
}

TEST(Schema, aWrittenSchemaHasItsMutantReplaced) {
    EXPECT_EQ(switched(entry("w", "{0.5f, 0.5f}", "{0.0f, 0.0f}", "MUTANT ? v{0, 0} : v{1, 1}")), "(ON) ? v{0, 0} : v{1, 1}");
}

TEST(Schema, refusesWhatItCannotSwitch) {
    const auto refused = [](const Entry& e) {
        try {
            switched(e);
        } catch (const CatalogueError& error) {
            return std::string(error.what());
        }
        return std::string();
    };
    EXPECT_NE(refused(entry("u", "f(a, b));", "f(b, a));")).find("bugs.txt:1: [u]: its find or replace text is not a "
                                                                  "whole expression"),
              std::string::npos);
    EXPECT_NE(refused(entry("r", "const int a = 1;", "int b = 1;")).find("does not declare the same way"),
              std::string::npos);
    EXPECT_NE(refused(entry("m", "a", "b", "no switch")).find("its schema has no MUTANT"), std::string::npos);
    EXPECT_NE(refused(entry("n", "a + b", "")).find("cannot be replaced by nothing"), std::string::npos);
}

TEST(Schema, nestedAndSharedRegionsSwitchEachEntry) {
    const Entry outer = entry("outer", "sort(v, [](int a, int b) { return a < b; });", "");
    const Entry inner = entry("inner", "return a < b;", "return a > b;");
    const Entry twin = entry("twin", "return a < b;", "return b < a;");
    const Catalogue catalogue{"bugs.txt", {outer, inner, twin}};
    const std::string source = "void f() { sort(v, [](int a, int b) { return a < b; }); }\n";
    const std::string out = schemata_source(
        catalogue, source, {{&catalogue.entries[0], 0}, {&catalogue.entries[1], 1}, {&catalogue.entries[2], 2}},
        "switch.h");
    EXPECT_EQ(out,
              "#include \"switch.h\"  // mutant schemata: generated from mutants/bugs.txt\n"
              "void f() { if (!(" + switch_expression(0) + ")) { sort(v, [](int a, int b) { if (" +
                  switch_expression(2) + ") { return b < a; } else { if (" + switch_expression(1) +
                  ") { return a > b; } else { return a < b; } } }); } }\n");
}

TEST(Schema, refusesStaleAndPartlyOverlappingEntries) {
    const Catalogue catalogue{"bugs.txt", {entry("a", "x + y", "x - y"), entry("b", "y * z", "z * y")}};
    EXPECT_THROW(schemata_source(catalogue, "int v = x + y * z;", {{&catalogue.entries[0], 0}, {&catalogue.entries[1], 1}},
                                 "s.h"),
                 CatalogueError);
    EXPECT_THROW(schemata_source(catalogue, "x + y; x + y;", {{&catalogue.entries[0], 0}}, "s.h"), CatalogueError);
    EXPECT_THROW(schemata_source(catalogue, "nothing", {{&catalogue.entries[0], 0}}, "s.h"), CatalogueError);
}

}  // namespace
}  // namespace raster::mutants
