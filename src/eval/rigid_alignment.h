#pragma once
// Closed-form alignment of point sets: rigid (Horn / Umeyama without scale), as
// evaluate_ate.py, and similarity (Umeyama with scale), as evo's --correct_scale.

#include <vector>

#include <Eigen/Core>

#include "core/pose.h"

namespace dynvo {

// The rotation + translation (no scale, no reflection) `target_from_source` minimising
// sum_i |R source_i + t - target_i|^2, computed exactly as align() in evaluate_ate.py
// (SVD of the transposed cross-covariance). Throws InputError when the lists differ in size
// or are empty.
Pose AlignRigid(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target);

// target ~ scale * R * source + t.
struct Similarity {
  double scale = 1.0;
  Pose rotation_translation = Pose::Identity();  // R and t
};

// The similarity minimising sum_i |s R source_i + t - target_i|^2 (Umeyama 1991, as evo's
// umeyama_alignment with_scale): R as AlignRigid, s = trace(D S) / sum |source_i - mean|^2,
// t = mean_target - s R mean_source. Throws InputError as AlignRigid, and when the source
// points are all equal.
Similarity AlignSimilarity(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target);

}  // namespace dynvo
