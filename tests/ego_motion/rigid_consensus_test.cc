#include "ego_motion/rigid_consensus.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace dynvo {
namespace {

// Frame t's tracks into t-1 of a static scene at 1-4 m and of a flat person at 1.3-1.4 m who
// holds most of the corners and walks 5 cm sideways between the frames, with frame t's depth.
struct TwoMotions {
  PointTracks tracks;
  cv::Mat depth = cv::Mat::zeros(480, 640, CV_32FC1);
  std::vector<uint8_t> is_static;
};

// `plane_depth` > 0 puts the static scene on the fronto-parallel plane at that depth.
TwoMotions MakeTwoMotions(int num_static, int num_person, unsigned seed, double plane_depth = 0.0) {
  const Camera camera;
  const Eigen::Isometry3d previous_from_current =
      Eigen::Translation3d(0.03, 0.01, 0.02) * Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitY());
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(10, 630), y(10, 470), person_x(250, 390), person_y(100, 400);
  std::uniform_real_distribution<double> static_depth(1.0, 4.0), person_depth(1.3, 1.4);
  TwoMotions m;
  for (int i = 0; i < num_static + num_person; ++i) {
    const bool is_static = i < num_static;
    const Eigen::Vector2d pixel = is_static ? Eigen::Vector2d(std::round(x(rng)), std::round(y(rng)))
                                            : Eigen::Vector2d(std::round(person_x(rng)), std::round(person_y(rng)));
    const double depth = is_static ? (plane_depth > 0.0 ? plane_depth : static_depth(rng)) : person_depth(rng);
    Eigen::Vector3d point = camera.Backproject(pixel, depth);
    if (!is_static) point -= Eigen::Vector3d(0.05, 0.0, 0.0);  // where the person was at t-1
    const Eigen::Vector2d previous = camera.Project(previous_from_current * point);
    m.tracks.current.emplace_back(static_cast<float>(pixel.x()), static_cast<float>(pixel.y()));
    m.tracks.previous.emplace_back(static_cast<float>(previous.x()), static_cast<float>(previous.y()));
    m.depth.at<float>(static_cast<int>(pixel.y()), static_cast<int>(pixel.x())) = static_cast<float>(depth);
    m.is_static.push_back(is_static ? 1 : 0);
  }
  return m;
}

TEST(RigidConsensus, HoldsTheStaticSceneAtEveryDepthWhereAHomographyFollowsThePerson) {
  const TwoMotions m = MakeTwoMotions(60, 120, 3);
  const HomographyOptions options;
  const HomographyEstimate homography = EstimateHomography(m.tracks.previous, m.tracks.current, options);
  ASSERT_TRUE(homography.ok);
  int person_in_homography = 0;
  for (size_t i = 0; i < m.is_static.size(); ++i) person_in_homography += !m.is_static[i] && homography.inliers[i];
  EXPECT_GT(person_in_homography, 100);  // the premise: the homography's consensus is the person's

  const RigidConsensus rigid = FindRigidConsensus(m.tracks, m.depth, Camera{}, options);
  ASSERT_TRUE(rigid.ok) << rigid.failure;
  EXPECT_EQ(rigid.inliers, m.is_static);
  EXPECT_EQ(rigid.num_inliers, 60);
}

TEST(RigidConsensus, ItsHomographyIsThePlanesAtTheInliersMedianDepth) {
  const TwoMotions m = MakeTwoMotions(60, 40, 11, 2.5);
  const RigidConsensus rigid = FindRigidConsensus(m.tracks, m.depth, Camera{}, HomographyOptions{});
  ASSERT_TRUE(rigid.ok) << rigid.failure;
  ASSERT_EQ(rigid.num_inliers, 60);
  double worst_px = 0.0;
  for (size_t i = 0; i < 60; ++i) {
    const Eigen::Vector3d p = rigid.current_from_previous *
                              Eigen::Vector3d(m.tracks.previous[i].x, m.tracks.previous[i].y, 1.0);
    worst_px = std::max(worst_px, std::hypot(p.x() / p.z() - m.tracks.current[i].x,
                                             p.y() / p.z() - m.tracks.current[i].y));
  }
  EXPECT_LT(worst_px, 0.05);  // the tracks' pixels are exact; the fit's error is the solver's
}

TEST(RigidConsensus, TracksWithoutDepthAreNeverInliers) {
  TwoMotions m = MakeTwoMotions(60, 0, 5);
  for (int i = 0; i < 10; ++i) {
    const cv::Point2f& p = m.tracks.current[static_cast<size_t>(i)];
    m.depth.at<float>(static_cast<int>(p.y), static_cast<int>(p.x)) = 0.0f;
  }
  const RigidConsensus rigid = FindRigidConsensus(m.tracks, m.depth, Camera{}, HomographyOptions{});
  ASSERT_TRUE(rigid.ok) << rigid.failure;
  EXPECT_EQ(rigid.num_inliers, 50);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(rigid.inliers[static_cast<size_t>(i)], 0);
}

TEST(RigidConsensus, TooFewTracksWithDepthIsNoConsensusWithItsReason) {
  const TwoMotions m = MakeTwoMotions(20, 0, 7);
  const RigidConsensus rigid = FindRigidConsensus(m.tracks, m.depth, Camera{}, HomographyOptions{});
  EXPECT_FALSE(rigid.ok);
  EXPECT_NE(rigid.failure.find("too few tracks with depth (20)"), std::string::npos) << rigid.failure;
  EXPECT_EQ(rigid.num_inliers, 0);
}

TEST(RigidConsensus, SelectTracksKeepsTheFlaggedOnesInOrder) {
  PointTracks tracks;
  for (int i = 0; i < 4; ++i) {
    tracks.previous.emplace_back(static_cast<float>(i), 0.0f);
    tracks.current.emplace_back(static_cast<float>(i), 1.0f);
  }
  const PointTracks selected = SelectTracks(tracks, {0, 1, 0, 1});
  ASSERT_EQ(selected.current.size(), 2u);
  EXPECT_EQ(selected.previous[0].x, 1.0f);
  EXPECT_EQ(selected.current[1].x, 3.0f);
}

}  // namespace
}  // namespace dynvo
