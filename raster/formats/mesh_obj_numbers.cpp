// OBJ numbers and indices by tinyobjloader's rules: its digit loop for values, atoi for indices, its corner grammar.
#include "raster/formats/mesh_obj_numbers.h"

#include <climits>
#include <cstdint>
#include <cmath>
#include <cstdlib>
#include <string>

namespace raster::obj {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }

size_t skip_blanks(std::string_view text, size_t at) {
    while (at < text.size() && is_blank(text[at])) ++at;
    return at;
}

size_t skip_word(std::string_view text, size_t at) {
    while (at < text.size() && !is_blank(text[at])) ++at;
    return at;
}

}  // namespace

std::optional<double> number_value(std::string_view word) {
    // tinyobjloader's tryParseDouble: the mantissa summed digit by digit, then scaled by ldexp(m * 5^e, e).
    static constexpr double kTenths[] = {1.0, 0.1, 0.01, 0.001, 0.0001, 0.00001, 0.000001, 0.0000001};
    auto digit_at = [&](size_t at) { return at < word.size() && is_digit(word[at]); };
    const bool negative = !word.empty() && word[0] == '-';
    size_t at = !word.empty() && (word[0] == '+' || word[0] == '-') ? 1 : 0;
    const bool leading_dot = at < word.size() && word[at] == '.';
    if (!leading_dot && !digit_at(at)) return std::nullopt;
    double mantissa = 0.0;
    for (; !leading_dot && digit_at(at); ++at) {
        mantissa *= 10;
        mantissa += word[at] - '0';
    }
    if (at < word.size() && word[at] == '.') {
        ++at;
        for (int64_t place = 1; digit_at(at); ++at, ++place)
            mantissa += (word[at] - '0') * (place < 8 ? kTenths[place] : std::pow(10.0, static_cast<double>(-place)));
    }
    // The exponent in 32 bits that wrap around, as tinyobjloader's int did past 2147483647 (its check stops only
    // exponents of eleven digits and more): "1e-2147483649" comes out as 10^2147483647.
    uint32_t exponent = 0;
    if (at < word.size() && (word[at] == 'e' || word[at] == 'E')) {
        ++at;
        const bool negative_exponent = at < word.size() && word[at] == '-';
        if (at < word.size() && (word[at] == '+' || word[at] == '-')) ++at;
        if (!digit_at(at)) return std::nullopt;
        for (; digit_at(at); ++at) {
            if (exponent > INT_MAX / 10) return std::nullopt;
            exponent = exponent * 10 + static_cast<uint32_t>(word[at] - '0');
        }
        if (negative_exponent) exponent = 0u - exponent;
    }
    const auto power = static_cast<int32_t>(exponent);
    const double magnitude = power != 0 ? std::ldexp(mantissa * std::pow(5.0, power), power) : mantissa;
    return (negative ? -1 : 1) * magnitude;
}

int atoi_value(std::string_view text) {
    // strtol reads no further than the first blank after the leading white space: copy only that much.
    const size_t start = text.find_first_not_of(" \t\n\v\f\r");
    if (start == std::string_view::npos) return 0;
    const std::string digits(text.substr(0, skip_word(text, start)));
    return static_cast<int>(std::strtol(digits.c_str(), nullptr, 10));
}

bool reads_corner(std::string_view text, size_t& at) {
    // tinyobjloader's parseTriple: an index, then up to two more after a '/' each (an empty middle one for v//vn).
    auto index_reads = [&] {
        const bool nonzero = atoi_value(text.substr(at)) != 0;
        while (at < text.size() && text[at] != '/' && !is_blank(text[at])) ++at;
        return nonzero;
    };
    auto slash = [&] {
        if (at == text.size() || text[at] != '/') return false;
        ++at;
        return true;
    };
    if (!index_reads()) return false;
    if (!slash()) return true;
    if (slash()) return index_reads();  // v//vn
    if (!index_reads()) return false;   // the texture index
    return !slash() || index_reads();
}

bool reads_corner_list(std::string_view rest, bool& has_corner) {
    // No blanks are skipped before the first corner: a blank there is read as an index by atoi, as tinyobjloader did.
    for (size_t at = 0; at < rest.size(); at = skip_blanks(rest, at)) {
        if (!reads_corner(rest, at)) return false;
        has_corner = true;
    }
    return true;
}

bool reads_skin_weights(std::string_view rest) {
    // A vertex id, then (joint id, weight) pairs; blanks after the vertex id count as a pair with no joint id.
    size_t at = skip_word(rest, skip_blanks(rest, 0));
    while (at < rest.size()) {
        const size_t joint = skip_blanks(rest, at);
        const size_t joint_end = skip_word(rest, joint);
        at = skip_word(rest, skip_blanks(rest, joint_end));
        const std::optional<double> joint_id = number_value(rest.substr(joint, joint_end - joint));
        if (!joint_id || static_cast<float>(*joint_id) < 0.0f) return false;
        at = skip_blanks(rest, at);
    }
    return true;
}

}  // namespace raster::obj
