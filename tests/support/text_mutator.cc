#include "support/text_mutator.h"

#include <cctype>
#include <vector>

namespace dynvo::test {
namespace {

const char* const kTokens[] = {"nan",  "-nan",   "inf", "-inf",     "1e308", "-1e308", "1e309",
                               "-0",   "1e-320", "0",   "-1",       "1e180", "1e12",   "18446744073709551616",
                               "0x10", "1,5",    "",    "\"text\"", "true",  "null",   "[]",
                               "{}",   "#",      ",",   "  ",       "\t",    "\r",     "\n",
                               "1.",   ".5e"};

}  // namespace

size_t TextMutator::Below(size_t n) { return n == 0 ? 0 : static_cast<size_t>(rng_() % n); }

std::string TextMutator::Mutate(const std::string& text) {
  std::string out = text;
  const size_t rounds = 1 + Below(4);
  for (size_t k = 0; k < rounds; ++k) MutateOnce(&out);
  return out;
}

void TextMutator::MutateOnce(std::string* text) {
  const size_t at = Below(text->size() + 1);
  switch (Below(8)) {
    case 0:  // flip a byte
      if (!text->empty()) (*text)[Below(text->size())] ^= static_cast<char>(1u << Below(8));
      break;
    case 1:  // insert any byte
      text->insert(at, 1, static_cast<char>(Below(256)));
      break;
    case 2:  // delete a run
      text->erase(at, Below(16) + 1);
      break;
    case 3:  // duplicate a run
      text->insert(at, text->substr(Below(text->size() + 1), Below(64)));
      break;
    case 4:
    case 5:
      ReplaceNumber(text);
      break;
    case 6:
      EditLines(text);
      break;
    default:  // truncate
      text->resize(at);
  }
}

void TextMutator::ReplaceNumber(std::string* text) {
  // The number (or word) around a random position, or an insertion point when there is none.
  size_t begin = Below(text->size() + 1), end = begin;
  const auto part = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+';
  };
  while (begin > 0 && part((*text)[begin - 1])) --begin;
  while (end < text->size() && part((*text)[end])) ++end;
  text->replace(begin, end - begin, kTokens[Below(sizeof(kTokens) / sizeof(kTokens[0]))]);
}

void TextMutator::EditLines(std::string* text) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < text->size()) {
    const size_t end = text->find('\n', start);
    lines.push_back(text->substr(start, end == std::string::npos ? std::string::npos : end - start + 1));
    start = end == std::string::npos ? text->size() : end + 1;
  }
  if (lines.empty()) return;
  const size_t k = Below(lines.size());
  switch (Below(4)) {
    case 0:
      lines.insert(lines.begin() + static_cast<long>(k), lines[k]);  // duplicated
      break;
    case 1:
      lines.erase(lines.begin() + static_cast<long>(k));  // dropped
      break;
    case 2:
      lines[k].resize(Below(lines[k].size() + 1));  // cut
      break;
    default:
      std::swap(lines[k], lines[Below(lines.size())]);  // out of order
  }
  text->clear();
  for (const std::string& line : lines) *text += line;
}

}  // namespace dynvo::test
