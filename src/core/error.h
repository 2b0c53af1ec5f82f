#pragma once
// Errors the user can act on: every message names the file (and line, or config key)
// and what was expected. Executables print what() and exit non-zero.

#include <sstream>
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

// Unless `ok`, throws InputError("<section>.<field> must be <rule>, got <value>"): an option
// out of range, named by its config key.
template <typename T>
void RequireOption(bool ok, const std::string& section, const std::string& field, const std::string& rule,
                   const T& value) {
  if (ok) return;
  std::ostringstream message;
  message << section << "." << field << " must be " << rule << ", got " << value;
  throw InputError(message.str());
}

}  // namespace dynvo
