#include "dataset/text_lines.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace dynvo {

std::vector<TextLine> SplitDataLines(const std::string& text) {
  std::vector<TextLine> lines;
  std::istringstream in(text);
  std::string raw;
  int number = 0;
  while (std::getline(in, raw)) {
    ++number;
    TextLine line;
    line.number = number;
    std::string field;
    for (char c : raw) {
      if (c == ' ' || c == '\t' || c == ',' || c == '\r') {
        if (!field.empty()) line.fields.push_back(std::move(field));
        field.clear();
      } else {
        field.push_back(c);
      }
    }
    if (!field.empty()) line.fields.push_back(std::move(field));
    if (line.fields.empty() || line.fields[0][0] == '#') continue;
    lines.push_back(std::move(line));
  }
  return lines;
}

std::filesystem::file_status PathStatus(const std::string& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory)
    ThrowFileError(path, 0, "cannot examine: " + ec.message());
  return status;
}

std::string ReadTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) ThrowFileError(path, 0, "cannot open file");
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

bool ParseDouble(const std::string& field, double* value) {
  // strtod would skip leading white space; a field is a number only as a whole.
  if (field.empty() || std::isspace(static_cast<unsigned char>(field[0]))) return false;
  const char* begin = field.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if (end != begin + field.size() || errno == ERANGE || !std::isfinite(v)) return false;
  *value = v;
  return true;
}

double ParseStampField(const std::string& field, const std::string& source, int line, const std::string& what) {
  double stamp = 0;
  if (!ParseDouble(field, &stamp)) ThrowFileError(source, line, what + " is not a finite number: '" + field + "'");
  if (std::abs(stamp) >= kMaxStampSeconds)
    ThrowFileError(source, line,
                   what + " " + field +
                       " is not a time in seconds (1e12 or more; nanoseconds? divide by 1e9): stamps are seconds");
  return stamp;
}

}  // namespace dynvo
