#pragma once
// Line splitting shared by the TUM text formats: CRLF endings, '#' comments, blank lines,
// and spaces, tabs or commas between fields.

#include <filesystem>
#include <string>
#include <vector>

namespace dynvo {

struct TextLine {
  int number = 0;                   // 1-based line number in the file
  std::vector<std::string> fields;  // non-empty fields of the line
};

// The data lines of `text`: comment and blank lines are skipped, fields split on
// spaces, tabs and commas.
std::vector<TextLine> SplitDataLines(const std::string& text);

// What is at `path`, without exceptions: absent (type not_found) when nothing is there.
// Throws InputError naming the path when it cannot be examined (a symlink loop, a name too
// long, no permission).
std::filesystem::file_status PathStatus(const std::string& path);

// Whole content of a file. Throws InputError "<path>: cannot open file" when unreadable.
std::string ReadTextFile(const std::string& path);

// Parses a whole field as a finite double; false when it is not one.
bool ParseDouble(const std::string& field, double* value);

// Timestamps are seconds below this in magnitude (the year 33658); larger ones are in other
// units (nanoseconds, say) or corrupt.
constexpr double kMaxStampSeconds = 1e12;

// A timestamp field (`what` names it in the message, e.g. "timestamp"): a finite number of
// seconds below kMaxStampSeconds in magnitude. Throws InputError naming source:line.
double ParseStampField(const std::string& field, const std::string& source, int line, const std::string& what);

}  // namespace dynvo
