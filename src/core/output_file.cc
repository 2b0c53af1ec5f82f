#include "core/output_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/error.h"

namespace dynvo {
namespace {

std::string SystemReason() { return errno != 0 ? std::string(": ") + std::strerror(errno) : std::string(); }

}  // namespace

AppendedFile::AppendedFile(const std::string& path) : path_(path) {
  errno = 0;
  out_.open(path, std::ios::binary | std::ios::trunc);
  if (!out_) ThrowFileError(path, 0, "cannot write file" + SystemReason());
}

void AppendedFile::Append(const std::string& text) {
  errno = 0;
  out_ << text;
  out_.flush();
  if (!out_) ThrowFileError(path_, 0, "write failed (disk full?)" + SystemReason());
}

void WriteFileAtomically(const std::string& path, const std::string& content) {
  const std::string temporary = path + ".tmp";
  errno = 0;
  std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
  if (!out) ThrowFileError(path, 0, "cannot write file" + SystemReason());
  out << content;
  out.flush();
  out.close();
  std::error_code ec;
  if (!out) {
    const std::string reason = SystemReason();
    std::filesystem::remove(temporary, ec);
    ThrowFileError(path, 0, "write failed (disk full?)" + reason);
  }
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    const std::string reason = ec.message();
    std::filesystem::remove(temporary, ec);
    ThrowFileError(path, 0, "cannot replace the file: " + reason);
  }
}

}  // namespace dynvo
