#include "synth/articulated_cutout.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "synth/procedural_texture.h"

namespace dynvo {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr uchar kNoPart = 255;

// Body proportions as fractions of the height from the top of the head (Drillis and
// Contini's segment lengths): chin, shoulders, elbows, hips, knees, hands; and the torso's
// half width as a share of the silhouette's width at the chest (arms hanging beside it), beyond
// which pixels above the hands belong to the arms.
constexpr double kNeckRow = 0.13, kShoulderRow = 0.18, kElbowRow = 0.34, kHipRow = 0.50, kKneeRow = 0.72;
constexpr double kHandRow = 0.56, kTorsoShareOfChest = 0.32;
// Relief: height toward the viewer grows with the distance to the silhouette's edge up to
// this fraction of the height (a torso's half depth), so limbs are rounded and thinner.
constexpr double kReliefDepth = 0.07;

struct Rows {
  double neck, shoulder, elbow, hip, knee, hand;
};

// Median over the rows from shoulders to hips of the silhouette's extent (pixels).
double ChestWidth(const cv::Mat& alpha, const Rows& r) {
  std::vector<int> widths;
  for (int y = static_cast<int>(r.shoulder); y < static_cast<int>(r.hip) && y < alpha.rows; ++y) {
    int first = -1, last = -1;
    for (int x = 0; x < alpha.cols; ++x)
      if (alpha.at<uchar>(y, x) >= 128) {
        if (first < 0) first = x;
        last = x;
      }
    if (first >= 0) widths.push_back(last - first + 1);
  }
  if (widths.empty()) return alpha.cols;
  std::nth_element(widths.begin(), widths.begin() + static_cast<long>(widths.size() / 2), widths.end());
  return widths[widths.size() / 2];
}

// One label per silhouette pixel (kNoPart elsewhere).
cv::Mat LabelParts(const cv::Mat& alpha, double centre, double half_width, const Rows& r) {
  cv::Mat labels(alpha.size(), CV_8U, cv::Scalar(kNoPart));
  for (int y = 0; y < alpha.rows; ++y) {
    const uchar* a = alpha.ptr<uchar>(y);
    uchar* l = labels.ptr<uchar>(y);
    for (int x = 0; x < alpha.cols; ++x) {
      if (a[x] < 128) continue;
      const bool left = x < centre - half_width, right = x >= centre + half_width;
      BodyPart part;
      if (y < r.neck)
        part = kHead;
      else if (left && y < r.hand)
        part = y < r.elbow ? kLeftUpperArm : kLeftForearm;
      else if (right && y < r.hand)
        part = y < r.elbow ? kRightUpperArm : kRightForearm;
      else if (y < r.hip)
        part = kTorso;
      else if (x < centre)
        part = y < r.knee ? kLeftThigh : kLeftShin;
      else
        part = y < r.knee ? kRightThigh : kRightShin;
      l[x] = static_cast<uchar>(part);
    }
  }
  return labels;
}

// Mean column of `part`'s pixels in rows [row0, row1), or `fallback` when it has none there.
double PartColumn(const cv::Mat& labels, BodyPart part, int row0, int row1, double fallback) {
  double sum = 0;
  int count = 0;
  for (int y = std::max(0, row0); y < std::min(labels.rows, row1); ++y)
    for (int x = 0; x < labels.cols; ++x)
      if (labels.at<uchar>(y, x) == part) {
        sum += x;
        ++count;
      }
  return count > 0 ? sum / count : fallback;
}

// Joint pixel (column, row) of each part: the point it turns about.
std::array<cv::Point2d, kNumBodyParts> JointPixels(const cv::Mat& labels, double centre, double half_width,
                                                   const Rows& r, int height) {
  std::array<cv::Point2d, kNumBodyParts> j;
  const int band = std::max(2, height / 50);
  auto at = [&](BodyPart part, double row, double fallback) {
    const int y = static_cast<int>(row);
    return cv::Point2d(PartColumn(labels, part, y - band, y + band, fallback), row);
  };
  j[kTorso] = {centre, r.hip};
  j[kHead] = {centre, r.neck};
  j[kLeftUpperArm] = at(kLeftUpperArm, r.shoulder, centre - half_width);
  j[kRightUpperArm] = at(kRightUpperArm, r.shoulder, centre + half_width);
  j[kLeftForearm] = at(kLeftForearm, r.elbow, j[kLeftUpperArm].x);
  j[kRightForearm] = at(kRightForearm, r.elbow, j[kRightUpperArm].x);
  j[kLeftThigh] = at(kLeftThigh, r.hip, centre - 0.5 * half_width);
  j[kRightThigh] = at(kRightThigh, r.hip, centre + 0.5 * half_width);
  j[kLeftShin] = at(kLeftShin, r.knee, j[kLeftThigh].x);
  j[kRightShin] = at(kRightShin, r.knee, j[kRightThigh].x);
  return j;
}

// Height toward the viewer in [0, 1]: the distance to the silhouette's edge, capped, smoothed.
cv::Mat ReliefMap(const cv::Mat& alpha, double cap_px) {
  cv::Mat inside = alpha >= 128, distance;
  cv::distanceTransform(inside, distance, cv::DIST_L2, 3);
  cv::Mat relief = cv::min(distance / cap_px, 1.0);
  cv::GaussianBlur(relief, relief, cv::Size(0, 0), std::max(1.0, 0.2 * cap_px));
  relief.setTo(0, ~inside);
  return relief;
}

// Rotation by `angle` about `axis` through `joint` (doll frame).
Pose TurnAbout(const Eigen::Vector3d& joint, const Eigen::Vector3d& axis, double angle) {
  return Pose(Eigen::Translation3d(joint) * Eigen::AngleAxisd(angle, axis) * Eigen::Translation3d(-joint));
}

Eigen::Vector3d Joint3(const ArticulatedCutout::Part& part) { return {part.joint.x(), 0, part.joint.y()}; }

// Doll-frame motion of every part for the pose (before the feet are planted).
std::array<Pose, kNumBodyParts> PartMotions(const ArticulatedCutout& doll, const BodyPose& pose,
                                            const Eigen::Vector3d& axis) {
  std::array<Pose, kNumBodyParts> m;
  m.fill(Pose::Identity());
  const auto& p = doll.parts;
  m[kHead] = TurnAbout(Joint3(p[kHead]), Eigen::Vector3d::UnitY(), pose.neck);
  const BodyPart upper[4] = {kLeftThigh, kRightThigh, kLeftUpperArm, kRightUpperArm};
  const BodyPart lower[4] = {kLeftShin, kRightShin, kLeftForearm, kRightForearm};
  for (int i = 0; i < 4; ++i) {
    const int side = i % 2;
    const bool leg = i < 2;
    const double turn = leg ? pose.hip[side] : pose.shoulder[side];
    const double bend = leg ? -pose.knee[side] : pose.elbow[side];
    m[upper[i]] = TurnAbout(Joint3(p[upper[i]]), axis, turn);
    m[lower[i]] = m[upper[i]] * TurnAbout(Joint3(p[lower[i]]), axis, bend);
  }
  return m;
}

TexturedQuad RestQuad(const ArticulatedCutout::Part& part) {
  TexturedQuad q;
  q.origin = {part.top_left.x(), part.behind_m, part.top_left.y()};
  q.edge_u = {part.size.x(), 0, 0};
  q.edge_v = {0, 0, -part.size.y()};
  q.texture = part.texture;
  return q;
}

}  // namespace

ArticulatedCutout MakeArticulatedCutout(const PersonCutout& cutout, double height_m) {
  if (cutout.bgra.empty() || cutout.bgra.type() != CV_8UC4) throw InputError("person cut-out must be 8-bit BGRA");
  if (cutout.bgra.rows < 40) throw InputError("person cut-out must be at least 40 pixels tall");
  const int h = cutout.bgra.rows, w = cutout.bgra.cols;
  cv::Mat alpha;
  cv::extractChannel(cutout.bgra, alpha, 3);
  const cv::Moments moments = cv::moments(alpha >= 128, true);
  const double centre = moments.m00 > 0 ? moments.m10 / moments.m00 : 0.5 * w;
  const Rows rows{kNeckRow * h, kShoulderRow * h, kElbowRow * h, kHipRow * h, kKneeRow * h, kHandRow * h};
  const double half_width = kTorsoShareOfChest * ChestWidth(alpha, rows);
  const cv::Mat labels = LabelParts(alpha, centre, half_width, rows);
  const auto joints = JointPixels(labels, centre, half_width, rows, h);
  const double scale = height_m / h;  // metres per pixel
  const cv::Mat relief = ReliefMap(alpha, kReliefDepth * h);

  ArticulatedCutout doll;
  doll.height_m = height_m;
  doll.width_m = w * scale;
  doll.relief_m = kReliefDepth * height_m;
  auto to_doll = [&](double x, double y) { return Eigen::Vector2d((x - centre) * scale, (h - y) * scale); };
  for (int k = 0; k < kNumBodyParts; ++k) {
    ArticulatedCutout::Part& part = doll.parts[static_cast<size_t>(k)];
    part.joint = to_doll(joints[static_cast<size_t>(k)].x, joints[static_cast<size_t>(k)].y);
    const cv::Mat mine = labels == k;
    const cv::Rect box = cv::boundingRect(mine);
    if (box.area() == 0) continue;
    cv::Mat bgra = cutout.bgra(box).clone();
    bgra.setTo(cv::Scalar(0, 0, 0, 0), ~mine(box));
    auto texture = std::make_shared<Texture>(*MakeTexture(bgra, scale));
    texture->relief = relief(box).clone();
    part.texture = texture;
    part.top_left = to_doll(box.x, box.y);
    part.size = {box.width * scale, box.height * scale};
    part.behind_m = (k == kTorso || k == kHead) ? 0.0 : 0.01;
  }
  return doll;
}

BodyPose WalkingPose(double phase_rad) {
  BodyPose pose;
  for (int side = 0; side < 2; ++side) {
    const double p = phase_rad + side * kPi;  // the right leg half a stride behind the left
    pose.hip[side] = 0.38 * std::sin(p);
    pose.knee[side] = 0.55 * std::max(0.0, std::sin(p + 0.9));  // bent while swinging forward
    pose.shoulder[side] = -0.3 * std::sin(p);
    pose.elbow[side] = 0.25 + 0.15 * std::max(0.0, -std::sin(p));
  }
  pose.lift_m = 0.015 * std::cos(2 * phase_rad);
  return pose;
}

BodyPose SittingPose(double rise, double seconds, double phase_rad) {
  BodyPose pose;
  const double seated = 1.0 - std::clamp(rise, 0.0, 1.0);
  for (int side = 0; side < 2; ++side) {
    const double wave = std::sin(2 * kPi * seconds / (3.7 + side) + phase_rad + side);
    pose.hip[side] = 0.5 * kPi * seated;
    pose.knee[side] = 0.5 * kPi * seated;
    pose.shoulder[side] = 0.25 * seated + 0.06 * wave;
    pose.elbow[side] = 0.9 * seated + 0.12 * wave;
  }
  pose.neck = 0.08 * std::sin(2 * kPi * seconds / 5.3 + phase_rad);
  return pose;
}

std::vector<TexturedQuad> PoseArticulatedCutout(const ArticulatedCutout& doll, const BodyPose& pose,
                                                const Pose& world_from_doll, const Eigen::Vector3d& swing_axis,
                                                int object_id) {
  const std::array<Pose, kNumBodyParts> motion = PartMotions(doll, pose, swing_axis.normalized());
  // Plant the lowest foot: the lowest corner of the shins at rest height 0, then lift.
  double lowest = std::numeric_limits<double>::infinity();
  for (BodyPart shin : {kLeftShin, kRightShin}) {
    const TexturedQuad q = RestQuad(doll.parts[shin]);
    if (!q.texture) continue;
    for (const Eigen::Vector3d& corner :
         {Eigen::Vector3d(q.origin + q.edge_v), Eigen::Vector3d(q.origin + q.edge_u + q.edge_v)})
      lowest = std::min(lowest, (motion[shin] * corner).z());
  }
  if (!std::isfinite(lowest)) lowest = 0;
  const Pose plant(Eigen::Translation3d(0, 0, pose.lift_m - lowest));
  std::vector<TexturedQuad> quads;
  for (int k = 0; k < kNumBodyParts; ++k) {
    const ArticulatedCutout::Part& part = doll.parts[static_cast<size_t>(k)];
    if (!part.texture) continue;
    TexturedQuad q = TransformQuad(world_from_doll * plant * motion[static_cast<size_t>(k)], RestQuad(part));
    q.object_id = object_id;
    q.relief_m = doll.relief_m;
    quads.push_back(q);
  }
  return quads;
}

}  // namespace dynvo
