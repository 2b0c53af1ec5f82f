#include "core/number_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace dynvo {
namespace {

// Enough for any finite double in fixed notation: sign, 309 integer digits, the point.
constexpr int kFixedDigits = 320;

}  // namespace

std::string FixedText(double value, int decimals) {
  std::string text(static_cast<size_t>(kFixedDigits + std::max(decimals, 0)), '\0');
  const auto result =
      std::to_chars(text.data(), text.data() + text.size(), value, std::chars_format::fixed, std::max(decimals, 0));
  text.resize(static_cast<size_t>(result.ptr - text.data()));
  return text;
}

std::string ShortText(double value) {
  std::string text(static_cast<size_t>(kFixedDigits), '\0');
  const auto result = std::to_chars(text.data(), text.data() + text.size(), value);
  text.resize(static_cast<size_t>(result.ptr - text.data()));
  return text;
}

std::string StampText(double stamp) {
  const std::string six = FixedText(stamp, 6);
  double back = 0;
  std::from_chars(six.data(), six.data() + six.size(), back);
  if (back == stamp || !std::isfinite(stamp)) return six;
  std::string text(static_cast<size_t>(kFixedDigits + 20), '\0');
  const auto result = std::to_chars(text.data(), text.data() + text.size(), stamp, std::chars_format::fixed);
  text.resize(static_cast<size_t>(result.ptr - text.data()));
  return text;
}

}  // namespace dynvo
