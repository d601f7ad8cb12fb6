// The texture properties: the mip chain keeps the mean; a constant texture renders constant; the level of detail
// grows along a receding plane; trilinear is continuous where the level changes; the wrap modes are periodic or
// mirrored as documented; a checkerboard seen in perspective lands where the camera's rays say.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/type_precision.hpp>

#include "properties/failure.h"
#include "properties/generators.h"
#include "properties/generators/primitives.h"
#include "properties/generators/textures.h"
#include "properties/printing.h"
#include "properties/property_registry.h"
#include "properties/stage_driver.h"
#include "raster/shading/texture_lookup.h"
#include "raster/geometry/vertex_stage.h"
#include "raster/texture/texture_sampler.h"

namespace raster::properties {

namespace {

std::shared_ptr<const Texture> chained(const TextureLevel& level) {
    auto texture = std::make_shared<Texture>();
    texture->levels.push_back(level);
    build_mip_chain(*texture);
    return texture;
}

glm::dvec3 mean_of(const TextureLevel& level) {
    glm::dvec3 sum(0.0);
    for (const glm::vec3& t : level.texels) sum += glm::dvec3(t);
    return sum / static_cast<double>(level.texels.size());
}

// A floor quad y = 0 over x in [-half, half], z in [z0, z1] (z1 < z0, away from a camera looking down -z), with
// texture coordinates (x, -z) / scale, in a scene that renders it unlit at 1 sample per pixel.
Scene floor_scene(float half, float z0, float z1, float scale, const TextureBinding& binding, int width, int height) {
    Scene scene;
    scene.path = "texture property";
    scene.settings.width = width;
    scene.settings.height = height;
    scene.settings.shading = ShadingMode::unlit;
    scene.settings.background = glm::vec3(0.0f);
    scene.camera.eye = {0.0f, 1.0f, 0.0f};
    scene.camera.target = {0.0f, 0.35f, -4.0f};
    scene.camera.fov_y_degrees = 60.0f;
    scene.camera.near = 0.05f;
    scene.camera.far = 1000.0f;
    SceneMesh mesh;
    mutable_data(mesh).positions = {{-half, 0, z0}, {half, 0, z0}, {half, 0, z1}, {-half, 0, z1}};
    mutable_data(mesh).triangles = {{{0, 1, 2}}, {{0, 2, 3}}};
    auto uv = [&](const glm::vec3& p) { return glm::vec2(p.x / scale, -p.z / scale); };
    for (const TriangleIndices& t : mesh.data->triangles)
        mutable_data(mesh).corner_uvs.push_back({{uv(mutable_data(mesh).positions[t.v[0]]), uv(mutable_data(mesh).positions[t.v[1]]),
                                         uv(mesh.data->positions[t.v[2]])}});
    mesh.material.color = glm::vec3(1.0f);
    mesh.material.texture = binding;
    scene.meshes.push_back(std::move(mesh));
    return scene;
}

// Where the camera's ray through screen point (sx, sy) meets y = 0 (docs/conventions.md: pixel centres at +0.5,
// ndc y up, the vertical field of view), in double; false when it does not meet the floor ahead.
bool floor_point(const Camera& camera, int width, int height, double sx, double sy, glm::dvec2& xz) {
    const glm::dvec3 eye(camera.eye), forward = glm::normalize(glm::dvec3(camera.target) - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tan_half = std::tan(static_cast<double>(camera.fov_y_degrees) * M_PI / 360.0);
    const double aspect = static_cast<double>(width) / height;
    const double nx = 2.0 * sx / width - 1.0, ny = 1.0 - 2.0 * sy / height;
    const glm::dvec3 direction = forward + nx * tan_half * aspect * right + ny * tan_half * up;
    if (!(direction.y < 0.0)) return false;
    const double t = -eye.y / direction.y;
    xz = {eye.x + t * direction.x, eye.z + t * direction.z};
    return true;
}

}  // namespace

// Every level's mean is level 0's, within the float rounding of each level (one rounding per level, relative):
// the area-weighted footprints tile the image exactly, odd sizes included. Point sampling, dropped rows or
// columns, or a wrong footprint for an odd size move the mean.
RASTER_PROPERTY(MipChain, keepsTheImagesMean) {
    static_cast<void>(impl);  // raster/texture's own functions: the sampler is not a pipeline stage
    const TextureImageCase c = *texture_images();
    RC_CLASSIFY(true, c.kind);
    const std::shared_ptr<const Texture> texture = chained(c.level);
    const glm::dvec3 mean = mean_of(c.level);
    if (texture->levels.size() != static_cast<size_t>(mip_level_count(c.level.width, c.level.height)))
        fail_case("the chain has " + std::to_string(texture->levels.size()) + " levels");
    for (size_t k = 1; k < texture->levels.size(); ++k) {
        const TextureLevel& level = texture->levels[k];
        if (level.width != std::max(1, texture->levels[k - 1].width / 2) ||
            level.height != std::max(1, texture->levels[k - 1].height / 2))
            fail_case("level " + std::to_string(k) + " is " + std::to_string(level.width) + " x " +
                      std::to_string(level.height));
        const glm::dvec3 m = mean_of(level);
        for (int ch = 0; ch < 3; ++ch)
            if (!(std::fabs(m[ch] - mean[ch]) <= 4.0 * (k + 1) * 0x1p-24))
                fail_case("level " + std::to_string(k) + " has mean " + double_literal(m[ch]) + ", level 0 " +
                          double_literal(mean[ch]));
    }
}

// Wrap, against its definition, at texel centres (where no rounding can move a lookup to a neighbour): repeat
// reads the same texel at u + n, mirror at 2n + u and 2n - u, clamp the edge texel past either end.
RASTER_PROPERTY(Wrap, repeatsMirrorsAndClampsAsDocumented) {
    static_cast<void>(impl);  // raster/texture's own functions: the sampler is not a pipeline stage
    const TextureImageCase c = *texture_images();
    const int i = *gen::inRange(0, c.level.width), j = *gen::inRange(0, c.level.height);
    const int n = *gen::inRange(-6, 7), m = *gen::inRange(-6, 7);
    const float u = (i + 0.5f) / c.level.width, v = 1.0f - (j + 0.5f) / c.level.height;  // row j from the top
    const glm::vec3& texel = c.level.at(i, j);
    auto check = [&](TextureWrap wrap, glm::vec2 uv, const glm::vec3& expected, const char* what) {
        if (sample_nearest(c.level, uv, wrap) != expected)
            fail_case(std::string(what) + " at " + literal(uv) + " does not read the expected texel");
    };
    check(TextureWrap::repeat, {u + n, v + m}, texel, "repeat");
    check(TextureWrap::mirror, {u + 2 * n, v + 2 * m}, texel, "mirror by whole periods");
    check(TextureWrap::mirror, {2 * n - u, 2 * m - v}, texel, "mirror reflected");
    if (n != 0) {
        const int edge_i = n > 0 ? c.level.width - 1 : 0;
        check(TextureWrap::clamp, {u + n, v}, c.level.at(edge_i, j), "clamp");
    }
}

// Trilinear has no jump where the level changes: across an integer lod k, values at k - d and k + d differ by at
// most 2 d times the largest level-to-level difference (at most 1 for texels in [0, 1]), plus float rounding.
RASTER_PROPERTY(Trilinear, isContinuousWhereTheLevelChanges) {
    static_cast<void>(impl);  // raster/texture's own functions: the sampler is not a pipeline stage
    const TextureImageCase c = *texture_images();
    const std::shared_ptr<const Texture> texture = chained(c.level);
    RC_PRE(texture->levels.size() >= 2);
    const int k = *gen::inRange(1, static_cast<int>(texture->levels.size()));
    const float d = 1.0f / 1024.0f;
    const glm::vec2 uv(static_cast<float>(signed_unit() * 3.0), static_cast<float>(signed_unit() * 3.0));
    const TextureWrap wrap = *texture_wraps();
    const glm::vec3 below = sample_trilinear(*texture, uv, k - d, wrap), above = sample_trilinear(*texture, uv, k + d, wrap);
    for (int ch = 0; ch < 3; ++ch)
        if (!(std::fabs(below[ch] - above[ch]) <= 2.0f * d + 1e-5f))
            fail_case("at lod " + std::to_string(k) + " -/+ 1/1024 the values are " + float_literal(below[ch]) + " and " +
                      float_literal(above[ch]) + " at " + literal(uv));
}

// Along a plane receding from the camera, every pixel further up the screen (further away) has a level of detail
// at least that of the pixel below it: the footprint only grows with distance.
RASTER_PROPERTY(LevelOfDetail, growsAlongARecedingPlane) {
    static_cast<void>(impl);  // raster/texture's own functions: the sampler is not a pipeline stage
    const int width = 160, height = 120;
    TextureLevel level;
    level.width = 1 << *gen::inRange(3, 11);
    level.height = 1 << *gen::inRange(3, 11);
    level.texels.assign(static_cast<size_t>(level.width) * level.height, glm::vec3(0.5f));
    TextureBinding binding;
    binding.texture = std::make_shared<Texture>(Texture{"", {level}});
    const float scale = static_cast<float>(log_uniform(0.05, 20.0));
    const Scene scene = floor_scene(50.0f, -0.5f, -400.0f, scale, binding, width, height);
    const TransformedScene geometry = run_vertex_stage(scene, vertex_stage_needs(scene.settings.shading));
    const TextureLookup lookup(scene, geometry);
    const int column = *gen::inRange(0, width);
    // The floor's barycentrics at a pixel centre, from the ray's floor point in the quad's first triangle (the one
    // with corners 0, 1, 2: x from -50 to 50 at z -0.5, to z -400 at x 50).
    float previous = -INFINITY;
    for (int row = height - 1; row >= 0; --row) {
        glm::dvec2 xz;
        if (!floor_point(scene.camera, width, height, column + 0.5, row + 0.5, xz)) break;
        const double z0 = -0.5, z1 = -400.0;
        const double b2 = (xz.y - z0) / (z1 - z0);           // towards corner 2 along z
        const double b1 = (xz.x + 50.0) / 100.0 - b2;        // corner 1 minus what corner 2 took
        const double b0 = 1.0 - b1 - b2;
        if (b0 < 0.0 || b1 < 0.0 || b2 < 0.0) continue;      // in the other triangle
        const TexturePoint point = lookup.at(0, glm::vec3(static_cast<float>(b0), static_cast<float>(b1), static_cast<float>(b2)));
        const float lod = texture_footprint(level, sampler_of(binding), point.duv_dx, point.duv_dy).lod;
        if (lod < previous - 1e-3f)
            fail_case("row " + std::to_string(row) + " (further away) has lod " + float_literal(lod) + " below the row under it, " +
                      float_literal(previous));
        previous = std::max(previous, lod);
    }
}

// A constant texture renders constant: whatever the filter, the wrap, the texture's size (mip levels of an odd size
// included) and the coordinates, every pixel the floor covers shows the texel's byte, k / 255 -> k.
RASTER_DRAWING_PROPERTY(Texture, aConstantTextureRendersConstant) {
    const int code = *gen::inRange(1, 256);
    TextureLevel level;
    level.width = *gen::inRange(1, 40);
    level.height = *gen::inRange(1, 40);
    level.texels.assign(static_cast<size_t>(level.width) * level.height, glm::vec3(code / 255.0f));
    TextureBinding binding;
    binding.filter = *texture_filters();
    binding.wrap = *texture_wraps();
    binding.max_anisotropy = *gen::inRange(1, 17);
    binding.texture = chained(level);
    RC_CLASSIFY(true, to_string(binding.filter));
    const Scene scene = floor_scene(30.0f, -0.3f, -300.0f, static_cast<float>(log_uniform(0.01, 50.0)), binding, 96, 64);
    const RenderResult result = render_with(impl, scene);
    for (int y = 0; y < result.image.height; ++y)
        for (int x = 0; x < result.image.width; ++x) {
            const uint8_t* p = result.image.at(x, y);
            if (p[0] == 0 && p[1] == 0 && p[2] == 0) continue;  // the background
            if (p[0] != code || p[1] != code || p[2] != code)
                fail_case("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is " + std::to_string(p[0]) + " for a texture of " +
                          std::to_string(code));
        }
}

// A checkerboard in perspective, drawn with nearest filtering: where the corners of a 0.1-pixel square around a
// pixel's centre (its one sample), traced through the camera onto the floor in double, all fall in one square of
// the board, the pixel shows that square's colour (the float error of raster's coordinates is far smaller). Affine
// texture coordinates bend the board's lines away from where the rays put them.
RASTER_DRAWING_PROPERTY(Texture, aCheckerboardInPerspectiveLandsWhereTheRaysSay) {
    const int width = 120, height = 90;
    TextureLevel board;
    board.width = board.height = 2;
    board.texels = {glm::vec3(1.0f), glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(1.0f)};
    TextureBinding binding;
    binding.filter = TextureFilter::nearest;
    binding.wrap = TextureWrap::repeat;
    binding.texture = chained(board);
    const float scale = static_cast<float>(log_uniform(0.5, 8.0));  // world units per repeat of the 2 x 2 board
    Scene scene = floor_scene(40.0f, -0.2f, -60.0f, scale, binding, width, height);
    scene.settings.background = glm::vec3(0.5f);
    scene.camera.eye.x = static_cast<float>(signed_unit() * 2.0);
    scene.camera.target.x = static_cast<float>(signed_unit() * 3.0);
    const RenderResult result = render_with(impl, scene);
    // The square of a floor point: texel (floor(2 u), floor(2 (1 - v))) of the board, u = x / scale, v = -z / scale,
    // white where the two indices have the same parity.
    auto square_of = [&](const glm::dvec2& xz) {
        return glm::i64vec2(static_cast<int64_t>(std::floor(2.0 * xz.x / scale)),
                            static_cast<int64_t>(std::floor(2.0 * (1.0 + xz.y / scale))));
    };
    int judged = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            // The corners of the little square, all in one square of the board (which is convex, so the little
            // square is inside it too).
            glm::i64vec2 square[4];
            bool inside = true;
            for (int k = 0; k < 4 && inside; ++k) {
                glm::dvec2 xz(0.0);
                inside = floor_point(scene.camera, width, height, x + 0.5 + (k & 1 ? 0.05 : -0.05),
                                     y + 0.5 + (k & 2 ? 0.05 : -0.05), xz) &&
                         xz.y < -0.2 && xz.y > -60.0 && std::fabs(xz.x) < 40.0;
                square[k] = square_of(xz);
                inside = inside && square[k] == square[0];
            }
            if (!inside) continue;
            ++judged;
            const bool white = ((square[0].x + square[0].y) % 2 + 2) % 2 == 0;
            const uint8_t shown = result.image.at(x, y)[0];
            if (shown != (white ? 255 : 0))
                fail_case("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") shows " + std::to_string(shown) +
                          " inside a " + (white ? "white" : "black") + " square (scale " + float_literal(scale) + ")");
        }
    RC_ASSERT(judged > width * height / 10);
}

}  // namespace raster::properties
