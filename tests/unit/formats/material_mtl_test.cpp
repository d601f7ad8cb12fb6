// MTL libraries: the values raster reads, map_Kd's options and file names, and the errors with their lines.
#include "raster/formats/material_mtl.h"

#include <gtest/gtest.h>

#include "raster/core/errors.h"

namespace raster {
namespace {

TEST(Mtl, readsTheCoefficientsOfEachMaterial) {
    const auto materials = parse_mtl("# two\nnewmtl red paint\nKa 0.1 0.2 0.3\nKd 0.5\nKs 1 1 1\nNs 96\nd 0.75\n"
                                     "illum 2\nNi 1.45\n\nnewmtl glass\nTr 0.25\n",
                                     "m.mtl");
    ASSERT_EQ(materials.size(), 2u);
    EXPECT_EQ(materials[0].name, "red paint");
    EXPECT_EQ(materials[0].line, 2);
    EXPECT_EQ(*materials[0].ambient, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(*materials[0].diffuse, glm::vec3(0.5f));
    EXPECT_EQ(*materials[0].exponent, 96.0f);
    EXPECT_EQ(*materials[0].opacity, 0.75f);
    EXPECT_FALSE(materials[0].diffuse_map);
    EXPECT_FALSE(materials[1].ambient);
    EXPECT_FLOAT_EQ(*materials[1].opacity, 0.75f);  // Tr is 1 - d
}

TEST(Mtl, mapKdSkipsOptionsKeepsClampAndNamesWithSpaces) {
    const auto materials =
        parse_mtl("newmtl a\nmap_Kd -s 2 2 1 -o 0.5 -clamp on -bm 1 my texture.png\r\nnewmtl b\nmap_Kd wood.jpg\n", "m.mtl");
    ASSERT_TRUE(materials[0].diffuse_map);
    EXPECT_EQ(materials[0].diffuse_map->file, "my texture.png");
    EXPECT_EQ(materials[0].diffuse_map->line, 2);
    EXPECT_TRUE(materials[0].diffuse_map->clamp);
    EXPECT_EQ(materials[1].diffuse_map->file, "wood.jpg");
    EXPECT_FALSE(materials[1].diffuse_map->clamp);
}

void expect_error_on_line(const std::string& text, int line, const std::string& words) {
    try {
        parse_mtl(text, "m.mtl");
        FAIL() << "no error for: " << text;
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "m.mtl");
        EXPECT_EQ(e.line(), line) << e.what();
        EXPECT_NE(e.message().find(words), std::string::npos) << e.what();
    }
}

TEST(Mtl, refusesBadValuesNamingTheLine) {
    expect_error_on_line("newmtl a\nKd 0.5 x 0.5\n", 2, "not a finite number");
    expect_error_on_line("newmtl a\nKd -1 0 0\n", 2, "must be in");
    expect_error_on_line("newmtl a\nd 1.5\n", 2, "must be in");
    expect_error_on_line("Kd 1 1 1\n", 1, "before any newmtl");
    expect_error_on_line("newmtl a\n\nmap_Kd -clamp on\n", 3, "names no image file");
    expect_error_on_line("newmtl a\nKd 1 1\n", 2, "1 or 3 values");
}

}  // namespace
}  // namespace raster
