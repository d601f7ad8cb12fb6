// Input errors: formats the "file:line:col: message" text once, for every loader.
#include "raster/core/errors.h"

#include <sstream>

namespace raster {
namespace {

std::string format_location(const std::string& file, int line, int column, const std::string& message) {
    std::ostringstream text;
    if (!file.empty()) text << file << ':';
    if (line > 0) {
        text << line << ':';
        if (column > 0) text << column << ':';
    }
    if (!file.empty() || line > 0) text << ' ';
    text << message;
    return text.str();
}

}  // namespace

InputError::InputError(std::string file, int line, int column, const std::string& message)
    : std::runtime_error(format_location(file, line, column, message)),
      file_(std::move(file)),
      line_(line),
      column_(column),
      message_(message) {}

}  // namespace raster
