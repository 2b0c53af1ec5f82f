#pragma once
// Output files that never lie: every write checked (a full disk is an error naming the
// file, not a short file and exit 0), and whole files replaced atomically.

#include <fstream>
#include <string>

namespace dynvo {

// A text file written piece by piece as a run goes (trajectory.txt, timing.csv).
class AppendedFile {
 public:
  // Creates or truncates the file. Throws InputError naming it when it cannot.
  explicit AppendedFile(const std::string& path);
  // Writes `text` and flushes it to the system. Throws InputError naming the file when the
  // write fails (disk full, file size limit, I/O error).
  void Append(const std::string& text);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::ofstream out_;
};

// Writes `content` to `path` as one step: into a temporary file beside it, flushed and
// closed, then renamed over `path`; a reader sees the old file or the new one, never a part.
// Throws InputError naming the file when any step fails (the temporary file is removed).
void WriteFileAtomically(const std::string& path, const std::string& content);

}  // namespace dynvo
