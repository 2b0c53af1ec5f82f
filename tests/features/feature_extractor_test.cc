#include "features/feature_extractor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <set>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/error.h"
#include "features/test_images.h"
#include "support/process_cpu_time.h"
#include "support/shared_data.h"

namespace dynvo {
namespace {

// Cells of an 8x6 grid over 640x480 holding at least one keypoint.
int CellsCovered(const std::vector<cv::KeyPoint>& keypoints) {
  std::set<int> cells;
  for (const cv::KeyPoint& k : keypoints)
    cells.insert(static_cast<int>(k.pt.y / 80) * 8 + static_cast<int>(k.pt.x / 80));
  return static_cast<int>(cells.size());
}

using test::ProcessCpuMs;

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

TEST(FeatureExtractor, OutputsAreConsistent) {
  FeatureExtractor extractor{FeatureOptions{}};
  const cv::Mat image = test::TexturedImage(1);
  const FrameFeatures f = extractor.Extract(image, cv::Mat(), Camera{});
  ASSERT_GE(f.size(), 950u);  // a fully textured image yields (nearly) the 1000 wanted
  EXPECT_LE(f.size(), 1000u);
  EXPECT_EQ(f.descriptors.rows, static_cast<int>(f.size()));
  EXPECT_EQ(f.descriptors.cols, 32);
  EXPECT_EQ(f.descriptors.type(), CV_8UC1);
  ASSERT_EQ(f.pixels.size(), f.size());
  ASSERT_EQ(f.depths.size(), f.size());
  ASSERT_EQ(f.points_in_camera.size(), f.size());
  std::set<int> octaves;
  for (size_t i = 0; i < f.size(); ++i) {
    const cv::KeyPoint& k = f.keypoints[i];
    EXPECT_TRUE(k.pt.x >= 0 && k.pt.y >= 0 && k.pt.x < 640 && k.pt.y < 480);
    EXPECT_TRUE(k.angle >= 0 && k.angle < 360);
    octaves.insert(k.octave);
    EXPECT_EQ(f.pixels[i], Eigen::Vector2d(k.pt.x, k.pt.y));  // no distortion: unchanged
    EXPECT_EQ(f.depths[i], 0.0);                              // no depth image
  }
  EXPECT_EQ(octaves.size(), 8u);  // every pyramid level contributes
}

TEST(FeatureExtractor, QuadtreeCoversMoreCellsThanPlainOrb) {
  const cv::Mat image = test::DenseCornerImage(2);
  FeatureExtractor extractor{FeatureOptions{}};
  const FrameFeatures f = extractor.Extract(image, cv::Mat(), Camera{});
  std::vector<cv::KeyPoint> orb;
  cv::ORB::create(1000)->detect(image, orb);
  const int ours = CellsCovered(f.keypoints), plain = CellsCovered(orb);
  std::cout << "cells covered (of 48): quadtree " << ours << " (" << f.size() << " features), cv::ORB " << plain << " ("
            << orb.size() << " features)\n";
  EXPECT_GE(ours, plain + 15);
  EXPECT_GE(ours, 40);
}

TEST(FeatureExtractor, DescriptorsFollowTheImage) {
  // The same texture shifted by (7, 3) pixels: features found again at the shifted position
  // (within the rounding of their pyramid level) carry nearly the same descriptor, whereas
  // unrelated ORB descriptors differ in about 128 of 256 bits. Wrong level coordinates or
  // angles would make them unrelated.
  const cv::Mat image = test::TexturedImage(3);
  cv::Mat shifted;
  const cv::Mat shift = (cv::Mat_<double>(2, 3) << 1, 0, 7, 0, 1, 3);
  cv::warpAffine(image, shifted, shift, image.size(), cv::INTER_NEAREST, cv::BORDER_REFLECT);
  FeatureExtractor extractor{FeatureOptions{}};
  const FrameFeatures a = extractor.Extract(image, cv::Mat(), Camera{});
  const FrameFeatures b = extractor.Extract(shifted, cv::Mat(), Camera{});
  std::vector<double> distances;
  std::vector<int> found_per_level(8, 0);
  int level0_identical = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const cv::KeyPoint& ka = a.keypoints[i];
    const cv::Point2f target = ka.pt + cv::Point2f(7, 3);
    const double tolerance = 0.75 * ka.size / 31.0 + 0.01;  // 0.75 level pixel
    for (size_t j = 0; j < b.size(); ++j) {
      if (b.keypoints[j].octave != ka.octave || cv::norm(b.keypoints[j].pt - target) > tolerance) continue;
      const double d =
          cv::norm(a.descriptors.row(static_cast<int>(i)), b.descriptors.row(static_cast<int>(j)), cv::NORM_HAMMING);
      distances.push_back(d);
      ++found_per_level[ka.octave];
      if (ka.octave == 0 && d == 0) ++level0_identical;
      break;
    }
  }
  ASSERT_GE(distances.size(), 0.3 * a.size());
  for (int l = 0; l < 8; ++l) EXPECT_GT(found_per_level[l], 5) << "level " << l;
  const double median = Median(distances);
  std::cout << "features " << a.size() << ", found again " << distances.size() << ", median Hamming " << median
            << ", level 0 identical " << level0_identical << " of " << found_per_level[0] << "\n";
  EXPECT_LE(median, 20.0);
  // At level 0 the shift is whole pixels: the same patch, the same descriptor.
  EXPECT_GE(level0_identical, 0.8 * found_per_level[0]);
}

TEST(FeatureExtractor, BackprojectsWithKnownDepth) {
  Camera camera;
  camera.fx = 517.3;
  camera.fy = 516.5;
  camera.cx = 318.6;
  camera.cy = 255.3;
  const cv::Mat image = test::TexturedImage(4);
  // A tilted plane: depth grows with the column, 1.5 m to 2.78 m.
  cv::Mat depth(480, 640, CV_32FC1);
  for (int y = 0; y < 480; ++y)
    for (int x = 0; x < 640; ++x) depth.at<float>(y, x) = 1.5f + 0.002f * x;
  FeatureExtractor extractor{FeatureOptions{}};
  const FrameFeatures f = extractor.Extract(image, depth, camera);
  ASSERT_GT(f.size(), 500u);
  for (size_t i = 0; i < f.size(); ++i) {
    const int x = cvRound(f.keypoints[i].pt.x);
    const double d = 1.5 + 0.002 * x;
    ASSERT_NEAR(f.depths[i], d, 1e-5);
    const Eigen::Vector3d expected((f.pixels[i].x() - camera.cx) / camera.fx * d,
                                   (f.pixels[i].y() - camera.cy) / camera.fy * d, d);
    ASSERT_NEAR((f.points_in_camera[i] - expected).norm(), 0.0, 1e-5);
    ASSERT_NEAR((camera.Project(f.points_in_camera[i]) - f.pixels[i]).norm(), 0.0, 1e-6);
  }
}

TEST(FeatureExtractor, InvalidAndFarDepthGiveNoPoint) {
  const cv::Mat image = test::TexturedImage(5);
  // Four vertical bands: valid 2 m, missing (0), NaN, too near (5 cm), too far (10 m).
  cv::Mat depth(480, 640, CV_32FC1, cv::Scalar(2.0f));
  depth.colRange(128, 256).setTo(0.0f);
  depth.colRange(256, 384).setTo(std::numeric_limits<float>::quiet_NaN());
  depth.colRange(384, 512).setTo(0.05f);
  depth.colRange(512, 640).setTo(10.0f);
  FeatureOptions options;  // valid range [0.1, 8] m
  FeatureExtractor extractor(options);
  const FrameFeatures f = extractor.Extract(image, depth, Camera{});
  int valid = 0;
  for (size_t i = 0; i < f.size(); ++i) {
    const int x = cvRound(f.keypoints[i].pt.x);
    if (x < 128) {
      EXPECT_EQ(f.depths[i], 2.0f);
      EXPECT_NEAR(f.points_in_camera[i].z(), 2.0, 1e-6);
      ++valid;
    } else {
      EXPECT_EQ(f.depths[i], 0.0) << "x " << x;
      EXPECT_EQ(f.points_in_camera[i], Eigen::Vector3d::Zero());
    }
  }
  EXPECT_GT(valid, 50);
  EXPECT_LT(valid, static_cast<int>(f.size()) - 300);
}

TEST(FeatureExtractor, UndistortsKeypoints) {
  Camera camera;  // TUM freiburg1 calibration
  camera.fx = 517.306408;
  camera.fy = 516.469215;
  camera.cx = 318.643040;
  camera.cy = 255.313989;
  camera.distortion = {0.262383, -0.953104, -0.005358, 0.002628, 1.163314};
  FeatureExtractor extractor{FeatureOptions{}};
  const FrameFeatures f = extractor.Extract(test::TexturedImage(6), cv::Mat(), camera);
  ASSERT_GT(f.size(), 500u);
  std::vector<cv::Point2f> detected, undistorted;
  for (const cv::KeyPoint& k : f.keypoints) detected.push_back(k.pt);
  cv::undistortPoints(detected, undistorted, camera.K(), camera.DistCoeffs(), cv::noArray(), camera.K());
  // Independent check: distorting the undistorted pixel again gives the detected one.
  std::vector<cv::Point3d> rays;
  for (const Eigen::Vector2d& p : f.pixels)
    rays.emplace_back((p.x() - camera.cx) / camera.fx, (p.y() - camera.cy) / camera.fy, 1.0);
  std::vector<cv::Point2d> redistorted;
  cv::projectPoints(rays, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), camera.K(), camera.DistCoeffs(), redistorted);
  double largest_shift = 0.0;
  for (size_t i = 0; i < f.size(); ++i) {
    EXPECT_NEAR(f.pixels[i].x(), undistorted[i].x, 1e-3);
    EXPECT_NEAR(f.pixels[i].y(), undistorted[i].y, 1e-3);
    EXPECT_NEAR(redistorted[i].x, detected[i].x, 0.05);
    EXPECT_NEAR(redistorted[i].y, detected[i].y, 0.05);
    largest_shift = std::max(largest_shift, cv::norm(undistorted[i] - detected[i]));
  }
  EXPECT_GT(largest_shift, 5.0);  // the distortion is real, the test is not vacuous
}

TEST(FeatureExtractor, ExcludeMaskKeepsDetectionOut) {
  const cv::Mat image = test::TexturedImage(7);
  cv::Mat exclude(480, 640, CV_8UC1, cv::Scalar(0));
  const cv::Rect person(200, 100, 200, 300);
  exclude(person).setTo(255);
  FeatureExtractor extractor{FeatureOptions{}};
  const FrameFeatures all = extractor.Extract(image, cv::Mat(), Camera{});
  const FrameFeatures outside = extractor.Extract(image, cv::Mat(), Camera{}, exclude);
  auto inside = [&](const FrameFeatures& f) {
    int count = 0;
    for (const cv::KeyPoint& k : f.keypoints)
      count += person.contains(cv::Point(cvRound(k.pt.x), cvRound(k.pt.y))) ? 1 : 0;
    return count;
  };
  EXPECT_GT(inside(all), 100);
  EXPECT_EQ(inside(outside), 0);
  EXPECT_GT(outside.size(), 800u);  // the budget goes to the rest of the image
}

// True when both have the same keypoints (position, angle, response, level) and descriptors.
void ExpectSameFeatures(const FrameFeatures& a, const FrameFeatures& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.keypoints[i].pt, b.keypoints[i].pt) << i;
    EXPECT_EQ(a.keypoints[i].angle, b.keypoints[i].angle) << i;
    EXPECT_EQ(a.keypoints[i].response, b.keypoints[i].response) << i;
    EXPECT_EQ(a.keypoints[i].octave, b.keypoints[i].octave) << i;
  }
  EXPECT_EQ(cv::norm(a.descriptors, b.descriptors, cv::NORM_HAMMING), 0.0);
}

TEST(FeatureExtractor, FromItsOwnCornersEqualsExtract) {
  const cv::Mat image = test::TexturedImage(11);
  Executor executor(2);
  for (bool parallel : {false, true}) {
    FeatureExtractor extractor(FeatureOptions{}, parallel ? &executor : nullptr);
    DetectedCorners corners;
    const FrameFeatures extracted = extractor.Extract(image, cv::Mat(), Camera{}, cv::Mat(), &corners);
    ASSERT_EQ(corners.levels.size(), 8u);
    EXPECT_EQ(corners.image_size, image.size());
    size_t detected = 0;
    for (const auto& level : corners.levels) detected += level.size();
    EXPECT_GT(detected, 2 * extracted.size());  // more detected than chosen: the choice is real
    ExpectSameFeatures(extractor.ExtractFromCorners(corners, image, cv::Mat(), Camera{}), extracted);
  }
}

TEST(FeatureExtractor, FromCornersChoosesDetectedCornersOffTheMaskAndDescribesTheGivenImage) {
  const cv::Mat image = test::TexturedImage(12);
  const cv::Rect person(220, 120, 160, 240);
  cv::Mat exclude(480, 640, CV_8UC1, cv::Scalar(0));
  exclude(person).setTo(255);
  // The image the caller describes on: the person's pixels replaced by other texture.
  cv::Mat filled = image.clone();
  test::TexturedImage(13)(person).copyTo(filled(person));
  FeatureExtractor extractor{FeatureOptions{}};
  DetectedCorners corners;
  const FrameFeatures all = extractor.Extract(image, cv::Mat(), Camera{}, cv::Mat(), &corners);
  const FrameFeatures on_image = extractor.ExtractFromCorners(corners, image, cv::Mat(), Camera{}, exclude);
  const FrameFeatures on_filled = extractor.ExtractFromCorners(corners, filled, cv::Mat(), Camera{}, exclude);

  // Off the mask, chosen among the detected corners of their level, the budget spent elsewhere.
  int all_inside = 0;
  for (const cv::KeyPoint& k : all.keypoints)
    all_inside += person.contains(cv::Point(cvRound(k.pt.x), cvRound(k.pt.y)));
  EXPECT_GT(all_inside, 50);
  EXPECT_GT(on_image.size(), all.size() - 40);
  for (const cv::KeyPoint& k : on_image.keypoints) {
    EXPECT_FALSE(person.contains(cv::Point(cvRound(k.pt.x), cvRound(k.pt.y)))) << k.pt;
    const double scale = std::pow(1.2, k.octave);
    const auto& level = corners.levels[static_cast<size_t>(k.octave)];
    const bool detected = std::any_of(level.begin(), level.end(), [&](const cv::KeyPoint& c) {
      return std::abs(c.pt.x * scale - k.pt.x) < 1e-3 && std::abs(c.pt.y * scale - k.pt.y) < 1e-3;
    });
    EXPECT_TRUE(detected) << k.pt << " level " << k.octave;
  }

  // The same corners either way; described on the image given: the patches that reach into the
  // replaced pixels change, the others do not.
  ASSERT_EQ(on_image.size(), on_filled.size());
  int near_changed = 0, far_same = 0, far = 0;
  for (size_t i = 0; i < on_image.size(); ++i) {
    const cv::KeyPoint& k = on_image.keypoints[i];
    ASSERT_EQ(k.pt, on_filled.keypoints[i].pt);
    const double reach = 25.0 * std::pow(1.2, k.octave);  // descriptor patch and blur, level-0 px
    const cv::Rect2d grown(person.x - reach, person.y - reach, person.width + 2 * reach, person.height + 2 * reach);
    const bool same = cv::norm(on_image.descriptors.row(static_cast<int>(i)),
                               on_filled.descriptors.row(static_cast<int>(i)), cv::NORM_HAMMING) == 0.0;
    if (grown.contains(cv::Point2d(k.pt.x, k.pt.y))) {
      near_changed += same ? 0 : 1;
    } else {
      ++far;
      far_same += same ? 1 : 0;
    }
  }
  EXPECT_GT(near_changed, 10);
  EXPECT_GT(far, 500);
  EXPECT_EQ(far_same, far);

  EXPECT_THROW(extractor.ExtractFromCorners(corners, image(cv::Rect(0, 0, 320, 240)).clone(), cv::Mat(), Camera{}),
               InputError);
  EXPECT_THROW(extractor.ExtractFromCorners(DetectedCorners{}, image, cv::Mat(), Camera{}), InputError);
}

TEST(FeatureExtractor, FromCornersReusesWhatExtractDescribedWhereThePixelsAreUnchanged) {
  const cv::Mat image = test::TexturedImage(12);
  const cv::Rect person(220, 120, 160, 240);
  cv::Mat exclude(480, 640, CV_8UC1, cv::Scalar(0));
  exclude(person).setTo(255);
  cv::Mat filled = image.clone();  // described on: the person's pixels replaced by other texture
  test::TexturedImage(13)(person).copyTo(filled(person));
  FeatureExtractor extractor{FeatureOptions{}};
  DetectedCorners corners;
  extractor.Extract(image, cv::Mat(), Camera{}, cv::Mat(), &corners);
  ASSERT_EQ(corners.described.size(), corners.levels.size());
  DetectedCorners without_description = corners;
  without_description.described.clear();

  // The same features as when every keypoint is described again (the same extractor, whose
  // pyramid buffers the first extraction's description must not share).
  const FrameFeatures reused = extractor.ExtractFromCorners(corners, filled, cv::Mat(), Camera{}, exclude);
  const FrameFeatures described_again =
      FeatureExtractor{FeatureOptions{}}.ExtractFromCorners(without_description, filled, cv::Mat(), Camera{}, exclude);
  ExpectSameFeatures(reused, described_again);

  // What is reused, and where: with the earlier descriptors zeroed, the keypoints away from the
  // replaced pixels carry zeros (taken over), those whose patch reaches them do not.
  for (DescribedLevel& level : corners.described) level.descriptors.setTo(0);
  const FrameFeatures marked = extractor.ExtractFromCorners(corners, filled, cv::Mat(), Camera{}, exclude);
  ASSERT_EQ(marked.size(), reused.size());
  int taken_over = 0;
  for (size_t i = 0; i < marked.size(); ++i) {
    const cv::KeyPoint& k = marked.keypoints[i];
    const double reach = 22.0 * std::pow(1.2, k.octave);  // the rotated pattern alone, level-0 px
    const cv::Rect2d grown(person.x - reach, person.y - reach, person.width + 2 * reach, person.height + 2 * reach);
    const bool zero = cv::countNonZero(marked.descriptors.row(static_cast<int>(i))) == 0;
    taken_over += zero ? 1 : 0;
    if (grown.contains(cv::Point2d(k.pt.x, k.pt.y))) {
      EXPECT_FALSE(zero) << k.pt << " level " << k.octave;
    }
  }
  EXPECT_GT(taken_over, static_cast<int>(marked.size()) / 2);
}

TEST(FeatureExtractor, DistributionsAndDeterminism) {
  const cv::Mat image = test::DenseCornerImage(8);
  for (FeatureDistribution d :
       {FeatureDistribution::kQuadtree, FeatureDistribution::kGrid, FeatureDistribution::kNone}) {
    FeatureOptions options;
    options.distribution = d;
    FeatureExtractor first(options), second(options);
    const FrameFeatures a = first.Extract(image, cv::Mat(), Camera{});
    const FrameFeatures b = second.Extract(image, cv::Mat(), Camera{});
    const FrameFeatures c = first.Extract(image, cv::Mat(), Camera{});  // buffers reused
    ASSERT_EQ(a.size(), b.size()) << ToString(d);
    ASSERT_EQ(a.size(), c.size()) << ToString(d);
    ASSERT_GT(a.size(), 100u);
    EXPECT_EQ(cv::norm(a.descriptors, b.descriptors, cv::NORM_L1), 0.0);
    EXPECT_EQ(cv::norm(a.descriptors, c.descriptors, cv::NORM_L1), 0.0);
    for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a.keypoints[i].pt, c.keypoints[i].pt);
  }
}

TEST(FeatureExtractor, ParallelLevelsGiveTheSameResult) {
  const cv::Mat image = test::TexturedImage(10);
  FeatureOptions options;
  FeatureExtractor sequential(options);
  Executor executor(3);
  FeatureExtractor parallel(options, &executor);
  const FrameFeatures a = sequential.Extract(image, cv::Mat(), Camera{});
  const FrameFeatures b = parallel.Extract(image, cv::Mat(), Camera{});
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(cv::norm(a.descriptors, b.descriptors, cv::NORM_L1), 0.0);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.keypoints[i].pt, b.keypoints[i].pt);
    EXPECT_EQ(a.keypoints[i].angle, b.keypoints[i].angle);
  }
}

TEST(FeatureExtractor, RejectsBadInput) {
  FeatureExtractor extractor{FeatureOptions{}};
  EXPECT_THROW(extractor.Extract(cv::Mat(), cv::Mat(), Camera{}), InputError);
  EXPECT_THROW(extractor.Extract(cv::Mat(480, 640, CV_8UC3), cv::Mat(), Camera{}), InputError);
  const cv::Mat image = test::TexturedImage(9);
  EXPECT_THROW(extractor.Extract(image, cv::Mat(480, 640, CV_16UC1), Camera{}), InputError);
  EXPECT_THROW(extractor.Extract(image, cv::Mat(240, 320, CV_32FC1), Camera{}), InputError);
  EXPECT_THROW(extractor.Extract(image, cv::Mat(), Camera{}, cv::Mat(480, 640, CV_32FC1)), InputError);
  FeatureOptions bad;
  bad.num_levels = 0;
  EXPECT_THROW(FeatureExtractor{bad}, InputError);
}

TEST(FeatureExtractor, TinyImageGivesNoFeatures) {
  FeatureExtractor extractor{FeatureOptions{}};
  const FrameFeatures f = extractor.Extract(cv::Mat(30, 30, CV_8UC1, cv::Scalar(9)), cv::Mat(), Camera{});
  EXPECT_EQ(f.size(), 0u);
  EXPECT_EQ(f.descriptors.cols, 32);
}

TEST(FeatureExtractor, RealImageTiming) {
  DYNVO_REQUIRE_SHARED(shared);
  const std::filesystem::path folder =
      std::filesystem::path(shared) / "data/tum/rgbd_dataset_freiburg1_rpy_head150/rgb";
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) files.push_back(entry.path());
  ASSERT_GE(files.size(), 10u);
  std::sort(files.begin(), files.end());
  files.resize(10);
  FeatureExtractor extractor{FeatureOptions{}};
  Executor executor(Executor::DefaultThreads() - 1);
  FeatureExtractor parallel(FeatureOptions{}, &executor);
  std::vector<double> ms, cpu_ms, orb_ms, orb_cpu_ms, parallel_ms;
  size_t fewest = 100000;
  int fewest_cells = 48, cells_margin = 48;
  cv::Ptr<cv::ORB> orb = cv::ORB::create(1000);
  for (int repeat = 0; repeat < 3; ++repeat)
    for (const auto& file : files) {
      const cv::Mat gray = cv::imread(file.string(), cv::IMREAD_GRAYSCALE);
      ASSERT_EQ(gray.size(), cv::Size(640, 480));
      const double c0 = ProcessCpuMs();
      const auto t0 = std::chrono::steady_clock::now();
      const FrameFeatures f = extractor.Extract(gray, cv::Mat(), Camera{});
      const auto t1 = std::chrono::steady_clock::now();
      cpu_ms.push_back(ProcessCpuMs() - c0);
      std::vector<cv::KeyPoint> k;
      cv::Mat d;
      const double c1 = ProcessCpuMs();
      orb->detectAndCompute(gray, cv::noArray(), k, d);
      const auto t2 = std::chrono::steady_clock::now();
      orb_cpu_ms.push_back(ProcessCpuMs() - c1);
      const auto t3 = std::chrono::steady_clock::now();
      parallel.Extract(gray, cv::Mat(), Camera{});
      parallel_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t3).count());
      ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      orb_ms.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
      fewest = std::min(fewest, f.size());
      fewest_cells = std::min(fewest_cells, CellsCovered(f.keypoints));
      cells_margin = std::min(cells_margin, CellsCovered(f.keypoints) - CellsCovered(k));
    }
  std::cout << "extraction on fr1_rpy 640x480: median " << Median(ms) << " ms wall, " << Median(cpu_ms)
            << " ms CPU (cv::ORB(1000) " << Median(orb_ms) << " ms wall, " << Median(orb_cpu_ms)
            << " ms CPU), parallel_levels " << Median(parallel_ms) << " ms wall, fewest features " << fewest
            << ", fewest cells " << fewest_cells << "/48, smallest lead over cv::ORB " << cells_margin << " cells\n";
  EXPECT_GE(fewest, 900u);
  EXPECT_GE(fewest_cells, 30);
  EXPECT_GE(cells_margin, 0);
}

}  // namespace
}  // namespace dynvo
