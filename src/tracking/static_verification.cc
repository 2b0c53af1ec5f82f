#include "tracking/static_verification.h"

#include <string>

#include "core/error.h"

namespace dynvo {

std::vector<Match> VerifyStaticFeatures(const std::vector<Eigen::Vector3d>& points_in_world,
                                        const cv::Mat& point_descriptors, const std::vector<float>* point_angles_deg,
                                        const FrameFeatures& masked, const Camera& camera,
                                        const Pose& camera_from_world, const MatchOptions& matching,
                                        double max_error_px, const std::vector<uint8_t>& taken) {
  if (taken.size() != points_in_world.size())
    throw InputError("VerifyStaticFeatures: `taken` has " + std::to_string(taken.size()) + " entries for " +
                     std::to_string(points_in_world.size()) + " points");
  std::vector<Match> verified;
  if (!(max_error_px > 0.0) || masked.size() == 0 || points_in_world.empty()) return verified;
  MatchOptions tight = matching;
  tight.search_radius_px = max_error_px;
  const std::vector<Match> matches =
      MatchByProjection(points_in_world, point_descriptors, masked, camera, camera_from_world, tight, point_angles_deg);
  // The matcher keeps only features within the search radius of the projection: with the
  // radius set to the bar, every match is within it.
  for (const Match& match : matches)
    if (!taken[static_cast<size_t>(match.point_index)]) verified.push_back(match);
  return verified;
}

}  // namespace dynvo
