#pragma once
// CSV fields of free text (notes, reasons): what a spreadsheet reads back as the same text.

#include <string>

namespace dynvo {

// `text` as one CSV field: quoted, with quotes doubled, when it holds a comma, a quote or a
// line break (line breaks become spaces); as it is otherwise.
std::string CsvText(const std::string& text);

}  // namespace dynvo
