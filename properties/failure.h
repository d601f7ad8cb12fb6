// Failing a property case with a sentence that says what went wrong, rather than the source text of a condition.
#pragma once

#include <string>

namespace raster::properties {

// Fails the current RapidCheck case with `message` (RapidCheck then shrinks and prints the counterexample).
[[noreturn]] void fail_case(const std::string& message);

}  // namespace raster::properties
