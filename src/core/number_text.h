#pragma once
// Decimal text of numbers for the files dynvo writes (trajectories, CSVs, reports): never
// truncated, whatever the magnitude, and independent of the locale.

#include <string>

namespace dynvo {

// As printf's "%.*f": `decimals` digits after the point, every digit before it.
std::string FixedText(double value, int decimals);

// The shortest text that reads back as `value` ("0.1", "1e+180", "542.822841"): for messages.
std::string ShortText(double value);

// A timestamp in seconds: 6 decimals (TUM's format) when that text reads back as the same
// double, else the shortest fixed-point text that does, so that distinct stamps stay
// distinct once written.
std::string StampText(double stamp);

}  // namespace dynvo
