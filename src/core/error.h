#pragma once
// Errors the user can act on: every message names the file (and line, or config key)
// and what was expected. Executables print what() and exit non-zero.

#include <stdexcept>
#include <string>

namespace dynvo {

// An input the user supplied is missing or malformed.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// "<file>:<line>: <message>", or "<file>: <message>" when line <= 0.
std::string FileMessage(const std::string& file, int line, const std::string& message);

// Throws InputError(FileMessage(file, line, message)).
[[noreturn]] void ThrowFileError(const std::string& file, int line, const std::string& message);

}  // namespace dynvo
