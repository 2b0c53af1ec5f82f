#include "dataset/image_list.h"

#include "core/error.h"
#include "dataset/text_lines.h"

namespace dynvo {

std::vector<ImageListEntry> ParseImageList(const std::string& text, const std::string& source) {
  std::vector<ImageListEntry> entries;
  for (const TextLine& line : SplitDataLines(text)) {
    if (line.fields.size() != 2)
      ThrowFileError(source, line.number,
                     "expected 2 columns 'timestamp filename', got " + std::to_string(line.fields.size()));
    ImageListEntry entry;
    entry.stamp = ParseStampField(line.fields[0], source, line.number, "timestamp");
    if (!entries.empty() && !(entry.stamp > entries.back().stamp))
      ThrowFileError(source, line.number,
                     "timestamps must strictly increase, got " + line.fields[0] + " after " +
                         std::to_string(entries.back().stamp) + " (line " + std::to_string(entries.back().line) + ")");
    entry.path = line.fields[1];
    entry.line = line.number;
    entries.push_back(std::move(entry));
  }
  return entries;
}

std::vector<ImageListEntry> ReadImageList(const std::string& list_path) {
  return ParseImageList(ReadTextFile(list_path), list_path);
}

}  // namespace dynvo
