#pragma once
// Coherent motion among the pose's inliers: a static map point's reprojection error is its own
// noise, independent of its neighbours', while the points of something that moves a little (a
// person swaying in a chair) share one displacement. A neighbourhood whose mean error departs
// from the frame's by many standard errors is moving, even when each of its points is within
// the pose's inlier bound.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace dynvo {

class ConfigRegistry;

struct CoherentMotionOptions {
  bool enabled = false;
  double radius_px = 80.0;       // neighbours: within this image distance (pixels, > 0) ...
  double max_depth_ratio = 0.1;  // ... and this relative depth difference (log, > 0)
  int min_neighbours = 5;        // a smaller neighbourhood (the point included) says nothing (>= 2)
  double min_z = 5.0;            // standard errors the neighbourhood's mean error must depart by (> 0)
  double min_sigma_px = 0.2;     // floor under the frame's robust error scale (pixels, > 0)
  // Used by the tracker: only map points created at most this many frames ago may be flagged.
  // An older point's shared departure is more often the drift between the keyframes that
  // placed it and the current ones than motion (0 = any age, >= 0).
  int max_point_age_frames = 60;

  // Throws InputError naming the key ("tracking.coherent_motion.radius_px ...") when out of range.
  void Check() const;
};

// The config keys of the coherent-motion test (section "tracking.coherent_motion"): enabled.
void BindConfigKeys(const std::string& prefix, CoherentMotionOptions* options, ConfigRegistry* registry);

// One flag per correspondence (1 = moves with its neighbours): pixels and residuals (observed
// minus projected, pixels) and depths (metres, > 0) of the pose's inliers. The frame's own error
// is a smooth field (affine in the pixel, fitted robustly: a pose a little off, a rolling
// shutter); what each point departs from it is averaged over its neighbours, and the point is
// flagged when that mean exceeds min_z x scale / sqrt(neighbours) (scale: 1.4826 x the median
// absolute departure per axis, at least min_sigma_px) and the point's own departure along the
// mean is at least half of it. Nothing is flagged among fewer than 10 points. Throws InputError
// when the sizes differ or the options are invalid.
std::vector<uint8_t> FlagCoherentMotion(const std::vector<Eigen::Vector2d>& pixels,
                                        const std::vector<Eigen::Vector2d>& residuals,
                                        const std::vector<double>& depths, const CoherentMotionOptions& options);

}  // namespace dynvo
