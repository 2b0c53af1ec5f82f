#pragma once
// Seeded mutations of text inputs, for the fuzz tests of the parsers and entry points: what
// a corrupt download, a hand edit or another tool's output puts in a file.

#include <cstdint>
#include <random>
#include <string>

namespace dynvo::test {

class TextMutator {
 public:
  explicit TextMutator(uint64_t seed) : rng_(seed) {}

  // 1 to 4 mutations of `text`: bytes flipped, inserted (any byte: NUL, CR, non-UTF-8) or
  // deleted; a run of bytes deleted or duplicated; a line duplicated, dropped or cut; a
  // number replaced by one parsers mishandle (nan, inf, 1e308, -0, 1e-320, 2^64, huge
  // stamps); or the text truncated. Deterministic for a seed.
  std::string Mutate(const std::string& text);

 private:
  size_t Below(size_t n);  // uniform in [0, n), 0 when n == 0
  void MutateOnce(std::string* text);
  void ReplaceNumber(std::string* text);
  void EditLines(std::string* text);

  std::mt19937_64 rng_;
};

}  // namespace dynvo::test
