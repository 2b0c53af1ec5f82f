#include "eval/trajectory_stamps.h"

#include <sstream>

#include "core/error.h"

namespace dynvo {

std::string FormatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::vector<double> IncreasingStamps(const Trajectory& trajectory, const std::string& name) {
  std::vector<double> stamps;
  stamps.reserve(trajectory.size());
  for (const StampedPose& p : trajectory) {
    if (!stamps.empty() && !(p.stamp > stamps.back()))
      throw InputError(name + " trajectory: stamps must strictly increase, got " + FormatNumber(p.stamp) + " after " +
                       FormatNumber(stamps.back()));
    stamps.push_back(p.stamp);
  }
  return stamps;
}

}  // namespace dynvo
