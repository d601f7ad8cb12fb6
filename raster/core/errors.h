// Input errors: the one exception type every loader throws, carrying file, line and column for the message.
#pragma once

#include <stdexcept>
#include <string>

namespace raster {

// Bad user input (a scene, a mesh, a flag). The CLI turns it into "file:line:col: error: message" and exit code 2.
// line and column are 1-based; 0 means "not known".
class InputError : public std::runtime_error {
public:
    InputError(std::string file, int line, int column, const std::string& message);
    explicit InputError(const std::string& message) : InputError("", 0, 0, message) {}

    const std::string& file() const { return file_; }
    int line() const { return line_; }
    int column() const { return column_; }
    const std::string& message() const { return message_; }

private:
    std::string file_;
    int line_;
    int column_;
    std::string message_;
};

}  // namespace raster
