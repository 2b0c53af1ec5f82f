#include "core/error.h"

namespace dynvo {

std::string FileMessage(const std::string& file, int line, const std::string& message) {
  if (line > 0) return file + ":" + std::to_string(line) + ": " + message;
  return file + ": " + message;
}

void ThrowFileError(const std::string& file, int line, const std::string& message) {
  throw InputError(FileMessage(file, line, message));
}

}  // namespace dynvo
