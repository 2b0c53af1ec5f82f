#pragma once
// Line splitting shared by the TUM text formats: CRLF endings, '#' comments, blank lines,
// and spaces, tabs or commas between fields.

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

// Whole content of a file. Throws InputError "<path>: cannot open file" when unreadable.
std::string ReadTextFile(const std::string& path);

// Parses a whole field as a finite double; false when it is not one.
bool ParseDouble(const std::string& field, double* value);

}  // namespace dynvo
