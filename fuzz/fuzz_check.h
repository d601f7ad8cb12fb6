// Invariant checks for fuzz targets: on failure they print both values (and where) to stderr, then trap, so the
// fuzzer records the input. Input errors are never checked this way: only properties that must always hold.
#pragma once

#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>

namespace raster::fuzz {

// Prints "file:line: check failed: a OP b" with both values and the context, then stops the process.
template <class A, class B, class Context>
[[noreturn]] void check_failed(const char* file, int line, const char* a_text, const char* op, const char* b_text,
                               const A& a, const B& b, const Context& context) {
    std::ostringstream message;
    message << std::setprecision(9) << file << ":" << line << ": check failed: " << a_text << " " << op << " "
            << b_text << "\n  " << a_text << " = " << a << "\n  " << b_text << " = " << b << "\n  where: "
            << context() << "\n";
    std::fputs(message.str().c_str(), stderr);
    std::fflush(stderr);
    __builtin_trap();
}

}  // namespace raster::fuzz

// FUZZ_CHECK_OP(a, <=, b, context): `context` is a callable returning a std::string, evaluated only on failure.
#define FUZZ_CHECK_OP(a, op, b, context)                                                                    \
    do {                                                                                                    \
        const auto& fuzz_check_a_ = (a);                                                                    \
        const auto& fuzz_check_b_ = (b);                                                                    \
        if (!(fuzz_check_a_ op fuzz_check_b_))                                                              \
            ::raster::fuzz::check_failed(__FILE__, __LINE__, #a, #op, #b, fuzz_check_a_, fuzz_check_b_, context); \
    } while (0)

#define FUZZ_CHECK_EQ(a, b, context) FUZZ_CHECK_OP(a, ==, b, context)
#define FUZZ_CHECK_LE(a, b, context) FUZZ_CHECK_OP(a, <=, b, context)
#define FUZZ_CHECK_GE(a, b, context) FUZZ_CHECK_OP(a, >=, b, context)
