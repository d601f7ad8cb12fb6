// Linear [0, 1] colour to an 8-bit value: the one rounding every written pixel goes through.
#pragma once

#include <cstdint>

namespace raster {

// Clamp, scale by 255, round half up (NaN gives 0). Its own header so that a change to it rebuilds only its users.
inline uint8_t to_byte(float value) {
    if (!(value > 0.0f)) return 0;
    if (value >= 1.0f) return 255;
    return static_cast<uint8_t>(value * 255.0f + 0.5f);  // < 256 here
}

}  // namespace raster
