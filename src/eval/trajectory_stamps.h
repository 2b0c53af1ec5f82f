#pragma once
// Stamps of trajectories under evaluation, checked, and numbers as error messages print them.

#include <string>
#include <vector>

#include "dataset/trajectory_io.h"

namespace dynvo {

// The stamps of `trajectory` in order. Throws InputError "<name> trajectory: stamps must
// strictly increase, ..." when they do not.
std::vector<double> IncreasingStamps(const Trajectory& trajectory, const std::string& name);

// `value` as an error message prints it (ostream's default formatting).
std::string FormatNumber(double value);

}  // namespace dynvo
