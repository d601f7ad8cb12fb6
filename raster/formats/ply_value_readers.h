// Internal to raster_formats (the PLY reader): the value readers of an ascii and a binary little-endian body. Both
// offer begin_instance, read_scalar (as double), read_integer, skip_list_items, end_instance, finish, and fail
// (which throws with the location of the last value read), so that ply_body.cpp reads elements once for both.
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>

#include "raster/core/errors.h"
#include "raster/formats/ply_header.h"
#include "raster/formats/ply_tokens.h"

namespace raster::ply {

// Ascii: one instance per non-blank line, errors at the line and column of the token at fault.
class AsciiReader {
public:
    AsciiReader(std::string_view body, int64_t first_line, const std::string& name)
        : body_(body), next_line_no_(first_line), name_(name) {}

    void begin_instance(const Element& e, uint64_t index) {
        if (!next_nonblank_line())
            throw InputError(name_, clamp_int(next_line_no_), 0,
                             "truncated body: file ends before " + printable(e.name) + " " + std::to_string(index) + " (0-based) of " +
                                 std::to_string(e.count));
        element_ = &e;
        index_ = index;
    }

    void end_instance() {
        skip_space();
        if (line_pos_ < line_.size()) {
            column_ = static_cast<int64_t>(line_pos_) + 1;
            fail("extra tokens at the end of the line for " + printable(element_->name) + " " + std::to_string(index_) +
                 " (0-based): " + quote(line_.substr(line_pos_)));
        }
    }

    void finish() {
        if (next_nonblank_line()) {
            skip_space();
            column_ = static_cast<int64_t>(line_pos_) + 1;
            fail("unexpected data after the last element: " + quote(line_.substr(line_pos_)));
        }
    }

    double read_scalar(Type t) {
        const std::string_view tok = next_token();
        if (is_integer(t)) return static_cast<double>(integer_from(tok, t));
        double v = 0;
        switch (parse_double(tok, v)) {
            case NumberError::None: return v;
            case NumberError::OutOfRange: fail("number " + quote(tok) + " is out of range");
            case NumberError::NotANumber: break;
        }
        fail("expected a number, got " + quote(tok));
    }

    int64_t read_integer(Type t) { return integer_from(next_token(), t); }

    void skip_list_items(Type t, int64_t count) {
        for (int64_t i = 0; i < count; ++i) read_scalar(t);  // each item consumes a token or throws: bounded by the line
    }

    [[noreturn]] void fail(const std::string& message) const { throw InputError(name_, clamp_int(line_no_), clamp_int(column_), message);
    }

private:
    int64_t integer_from(std::string_view tok, Type t) {
        int64_t v = 0;
        switch (parse_int64(tok, v)) {
            case NumberError::None: break;
            case NumberError::OutOfRange: fail("integer " + quote(tok) + " is out of range for type " + type_name(t));
            case NumberError::NotANumber: fail("expected an integer (" + std::string(type_name(t)) + "), got " + quote(tok));
        }
        if (v < type_min(t) || v > type_max(t))
            fail("integer " + quote(tok) + " is out of range for type " + type_name(t));
        return v;
    }

    std::string_view next_token() {
        skip_space();
        if (line_pos_ >= line_.size()) {
            column_ = static_cast<int64_t>(line_.size()) + 1;
            fail("line ends early: " + printable(element_->name) + " " + std::to_string(index_) +
                 " (0-based) needs more values");
        }
        const size_t start = line_pos_;
        while (line_pos_ < line_.size() && !is_space(line_[line_pos_])) ++line_pos_;
        column_ = static_cast<int64_t>(start) + 1;
        return line_.substr(start, line_pos_ - start);
    }

    void skip_space() {
        while (line_pos_ < line_.size() && is_space(line_[line_pos_])) ++line_pos_;
    }

    bool next_nonblank_line() {
        while (pos_ < body_.size()) {
            const size_t nl = body_.find('\n', pos_);
            const size_t end = nl == std::string_view::npos ? body_.size() : nl;
            line_ = body_.substr(pos_, end - pos_);
            pos_ = nl == std::string_view::npos ? body_.size() : nl + 1;
            line_no_ = next_line_no_++;
            line_pos_ = 0;
            column_ = 0;
            skip_space();
            if (line_pos_ < line_.size()) return true;
        }
        return false;
    }

    std::string_view body_;
    size_t pos_ = 0;
    int64_t next_line_no_;
    int64_t line_no_ = 0;
    std::string_view line_;
    size_t line_pos_ = 0;
    int64_t column_ = 0;
    const Element* element_ = nullptr;
    uint64_t index_ = 0;
    const std::string& name_;
};

inline uint64_t saturating_mul(uint64_t a, uint64_t b) {
    if (a != 0 && b > std::numeric_limits<uint64_t>::max() / a) return std::numeric_limits<uint64_t>::max();
    return a * b;
}

// Binary little-endian: errors on line 0, naming the byte offset of the value at fault in the file.
class BinaryReader {
public:
    BinaryReader(std::string_view body, size_t body_offset, const std::string& name)
        : body_(body), base_(body_offset), name_(name) {}

    void begin_instance(const Element& e, uint64_t index) {
        element_ = &e;
        index_ = index;
    }
    void end_instance() {}

    void finish() {
        value_pos_ = pos_;
        if (pos_ != body_.size())
            fail(std::to_string(body_.size() - pos_) + " unexpected bytes after the last element");
    }

    double read_scalar(Type t) {
        const uint64_t bits = take(t);
        switch (t) {
            case Type::Int8: return static_cast<int8_t>(bits);
            case Type::UInt8:
            case Type::UInt16:
            case Type::UInt32: return static_cast<double>(bits);
            case Type::Int16: return static_cast<int16_t>(bits);
            case Type::Int32: return static_cast<int32_t>(bits);
            case Type::Float32: {
                const auto u = static_cast<uint32_t>(bits);
                float f;
                std::memcpy(&f, &u, sizeof f);
                return f;
            }
            case Type::Float64: {
                double d;
                std::memcpy(&d, &bits, sizeof d);
                return d;
            }
        }
        return 0;
    }

    int64_t read_integer(Type t) { return static_cast<int64_t>(read_scalar(t)); }  // integer types only: exact

    void skip_list_items(Type t, int64_t count) {
        value_pos_ = pos_;
        const uint64_t bytes = saturating_mul(static_cast<uint64_t>(count), type_size(t));
        if (bytes > body_.size() - pos_) truncated();
        pos_ += bytes;
    }

    [[noreturn]] void fail(const std::string& message) const {
        throw InputError(name_, 0, 0, message + " (at byte offset " + std::to_string(base_ + value_pos_) + ")");
    }

private:
    uint64_t take(Type t) {
        value_pos_ = pos_;
        const size_t n = type_size(t);
        if (n > body_.size() - pos_) truncated();
        uint64_t bits = 0;
        for (size_t i = 0; i < n; ++i) bits |= uint64_t{static_cast<unsigned char>(body_[pos_ + i])} << (8 * i);
        pos_ += n;
        return bits;
    }

    [[noreturn]] void truncated() const {
        fail("truncated body: file ends inside " + printable(element_->name) + " " + std::to_string(index_) + " (0-based) of " +
             std::to_string(element_->count));
    }

    std::string_view body_;
    size_t base_;
    size_t pos_ = 0;
    size_t value_pos_ = 0;
    const Element* element_ = nullptr;
    uint64_t index_ = 0;
    const std::string& name_;
};

}  // namespace raster::ply
