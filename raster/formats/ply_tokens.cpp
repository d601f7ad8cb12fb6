// PLY tokens and numbers: from_chars with a leading '+' and underflow as zero, file text quoted for messages.
#include "raster/formats/ply_tokens.h"

#include <charconv>
#include <system_error>

namespace raster::ply {

std::string printable(std::string_view s) {
    constexpr size_t kMaxShown = 40;
    std::string out;
    for (size_t i = 0; i < s.size() && i < kMaxShown; ++i) {
        const auto c = static_cast<unsigned char>(s[i]);
        if (c >= 0x20 && c < 0x7f && c != '\'') {
            out += static_cast<char>(c);
        } else {
            static constexpr char kHex[] = "0123456789abcdef";
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        }
    }
    if (s.size() > kMaxShown) out += "...";
    return out;
}

std::string quote(std::string_view s) {
    std::string quoted = "'";  // built in place: "'" + printable(s) trips GCC 12's -Wrestrict
    quoted += printable(s);
    quoted += '\'';
    return quoted;
}

std::string_view strip_plus(std::string_view s) {
    if (s.size() >= 2 && s[0] == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
    return s;
}

NumberError parse_int64(std::string_view token, int64_t& out) {
    const std::string_view s = strip_plus(token);
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    if (ec == std::errc::result_out_of_range && end == s.data() + s.size()) return NumberError::OutOfRange;
    if (ec != std::errc() || end != s.data() + s.size()) return NumberError::NotANumber;
    return NumberError::None;
}

NumberError parse_double(std::string_view token, double& out) {
    const std::string_view s = strip_plus(token);
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out, std::chars_format::general);
    if (end != s.data() + s.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
        return NumberError::NotANumber;
    if (ec == std::errc::result_out_of_range) {
        // libstdc++ also reports underflow as out of range: a negative exponent means the value is (nearly) zero.
        const bool negative_exponent = s.find("e-") != std::string_view::npos || s.find("E-") != std::string_view::npos;
        if (!negative_exponent) return NumberError::OutOfRange;
        out = s[0] == '-' ? -0.0 : 0.0;
    }
    return NumberError::None;
}

}  // namespace raster::ply
