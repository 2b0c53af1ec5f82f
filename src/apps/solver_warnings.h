#pragma once
// Ceres reports through glog, at WARNING level and whatever its solver's logging option says,
// steps it rejected on the way to a solution ("Linear solver failure. Failed to compute a step:
// Eigen failure. Unable to perform dense Cholesky factorization."). dynvo takes every solve's
// outcome from its summary and reports what matters in timing.csv and run.json, so on a user's
// terminal those lines are noise, headed by glog's "Logging before InitGoogleLogging()".

namespace dynvo {

// From the call on, glog (and with it Ceres) prints messages of level ERROR and above only, to
// stderr as before; warnings and info are dropped. For executables: a library leaves the
// process's logging alone.
void ShowOnlySolverErrors();

}  // namespace dynvo
