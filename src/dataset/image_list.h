#pragma once
// TUM image lists ("timestamp filename" per line): rgb.txt, depth.txt and our masks.txt.
// '#' comments, blank lines, CRLF endings and spaces, tabs or commas between fields are
// accepted, as in the TUM benchmark scripts.

#include <string>
#include <vector>

namespace dynvo {

struct ImageListEntry {
  double stamp = 0;  // seconds
  std::string path;  // as written, relative to the sequence folder
  int line = 0;      // 1-based line number in the list file
};

// The entries of an image list, in file order. Throws InputError naming file:line for: a
// missing file, a line without exactly 2 fields, a stamp that is not a finite number, or
// stamps that do not strictly increase.
std::vector<ImageListEntry> ReadImageList(const std::string& list_path);

// Parses image list text; `source` names it in error messages. Same rules as ReadImageList.
std::vector<ImageListEntry> ParseImageList(const std::string& text, const std::string& source);

}  // namespace dynvo
