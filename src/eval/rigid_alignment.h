#pragma once
// Closed-form rigid alignment of point sets (Horn / Umeyama without scale), as evaluate_ate.py.

#include <vector>

#include <Eigen/Core>

#include "core/pose.h"

namespace dynvo {

// The rotation + translation (no scale, no reflection) `target_from_source` minimising
// sum_i |R source_i + t - target_i|^2, computed exactly as align() in evaluate_ate.py
// (SVD of the transposed cross-covariance). Throws InputError when the lists differ in size
// or are empty.
Pose AlignRigid(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target);

}  // namespace dynvo
