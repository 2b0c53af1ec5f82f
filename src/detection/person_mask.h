#pragma once
// A detection box to a person's mask by depth: the person is the dominant near depth mode where
// its head and torso are in the box (not a desk in front of its legs), grown to its silhouette
// by depth continuity (a little beyond the box, where an arm or a foot sticks out; with
// ArmsBesideTheBox also across a limb's depth shadow and far beside the box, where an arm is
// held out, but nothing larger than a limb); what the box
// shows behind the person (background between the legs, beside the shoulders) stays out of the
// mask and usable.

#include <optional>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"

namespace dynvo {

struct PersonMaskOptions {
  double box_margin = 0.1;  // the silhouette may reach this share of the box's size beyond it
  // Beyond the margin (ArmsBesideTheBox; the defaults keep to the margin): beside the box the
  // silhouette may reach side_reach of the box's width (an arm held out, which a detector often
  // boxes without) over the box's rows above side_reach_rows of its height (not the feet, where
  // the floor lies at the person's depth); what lies beyond the margin stays only up to limb_share
  // of what lies within; in-band depths closer than link_px count as one part (a limb parted from
  // the torso by a depth shadow).
  double side_reach = 0.0;
  double side_reach_rows = 0.85;
  double limb_share = 0.15;
  int link_px = 0;
  double bin_ratio = 0.04;  // depth histogram bins, each this relative width (log depth)
  double dominance = 0.5;   // a depth mode counts with at least this share of the largest one's depths;
                            // the nearest of those is the person
  double band_m = 0.3;      // the person's depths: its mode +- max(band_m, band_ratio x depth)
  double band_ratio = 0.12;
  int grow_px = 6;               // the silhouette grown by this much (depth/colour misalignment, hair)
  double min_depth_share = 0.1;  // with fewer depths in the torso strip than this share, the whole box is the mask
};

// Options that reach an arm held out beside the box (side_reach 0.7, link_px 5). The recommended
// config's people use them (dev and validation better); the second paper's detector mask keeps
// to the box's margin (dev unchanged with them).
PersonMaskOptions ArmsBesideTheBox();

// The mask (CV_8UC1 of depth's size, 255 = the person) of the person detected in `box` (image
// pixels), from depth (CV_32FC1 metres, 0 = no measurement). Empty box: an empty mask.
cv::Mat PersonMaskFromBox(const cv::Mat& depth, const cv::Rect2d& box, const PersonMaskOptions& options = {});

// The depth of the person in `box`: in the box's head and torso strip (its middle half of the
// columns, from a tenth to six tenths of its height), the nearest depth mode holding at least
// `dominance` of the largest mode's depths; 0 when the strip has too few depths
// (min_depth_share).
double PersonDepth(const cv::Mat& depth, const cv::Rect& box, const PersonMaskOptions& options = {});

// Where the person of `silhouette` (CV_8UC1, 255 = the person, e.g. PersonMaskFromBox's) is, in
// the camera: the per-axis median of its back-projected pixels that have depth (every 4th row and
// column), robust to the background and limbs a silhouette takes in or loses as its box changes;
// nullopt when none has depth.
std::optional<Eigen::Vector3d> PersonCentre(const cv::Mat& silhouette, const cv::Mat& depth, const Camera& camera);

enum class PersonEndSide { kTop, kBottom };

// The top end of the person of `silhouette` (their head, when it is in view) or their bottom end,
// in the camera: PersonCentre's point at the height (camera y) of the silhouette's topmost (or
// lowest) points, of those within a body's depth of its median depth, so that the background the
// silhouette's margin takes in above or below them is not the end. The height is the 6th point
// from the end, past stray edge points; it does not move as the opposite end enters or leaves the
// view. nullopt when too few points have depth.
std::optional<Eigen::Vector3d> PersonEnd(const cv::Mat& silhouette, const cv::Mat& depth, const Camera& camera,
                                         PersonEndSide side);

}  // namespace dynvo
