// The texture generators: image sizes from 1 x 1 to 48 x 48 and odd shapes, texels k / 255.
#include "properties/generators/textures.h"

#include "properties/generators/primitives.h"

namespace raster::properties {

std::ostream& operator<<(std::ostream& os, const TextureImageCase& c) {
    os << "TextureImageCase{\"" << c.kind << "\", " << c.level.width << " x " << c.level.height << ", texels {";
    for (size_t i = 0; i < c.level.texels.size() && i < 64; ++i)
        os << (i ? ", " : "") << int(c.level.texels[i].x * 255.0f + 0.5f) << "/" << int(c.level.texels[i].y * 255.0f + 0.5f)
           << "/" << int(c.level.texels[i].z * 255.0f + 0.5f);
    return os << (c.level.texels.size() > 64 ? ", ..." : "") << "}}";
}

Gen<TextureImageCase> texture_images() {
    return gen::exec([] {
        TextureImageCase c;
        const int kind = *gen::weightedElement<int>({{4, 0}, {1, 1}, {1, 2}, {1, 3}});
        const char* names[] = {"random size", "power of two", "one row", "one column"};
        c.kind = names[kind];
        int w = *gen::inRange(1, 49), h = *gen::inRange(1, 49);
        if (kind == 1) w = 1 << *gen::inRange(0, 6), h = 1 << *gen::inRange(0, 6);
        if (kind == 2) h = 1;
        if (kind == 3) w = 1;
        c.level.width = w;
        c.level.height = h;
        for (int i = 0; i < w * h; ++i) {
            const auto code = [] { return static_cast<float>(*gen::inRange(0, 256)) / 255.0f; };
            c.level.texels.emplace_back(code(), code(), code());
        }
        return c;
    });
}

Gen<TextureWrap> texture_wraps() {
    return gen::element(TextureWrap::repeat, TextureWrap::clamp, TextureWrap::mirror);
}

Gen<TextureFilter> texture_filters() {
    return gen::element(TextureFilter::nearest, TextureFilter::bilinear, TextureFilter::trilinear,
                        TextureFilter::anisotropic);
}

}  // namespace raster::properties
