#include "dataset/tum_dataset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "dataset/camera_file.h"
#include "dataset/known_cameras.h"
#include "support/input_error.h"
#include "support/temp_dir.h"
#include "tum_test_folder.h"

namespace dynvo {
namespace {

using test::TempDir;
using test::TumTestFolder;
using test::TumTestFolderSpec;
using test::WriteTumTestFolder;

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(TumDatasetOptions, CheckNamesTheKey) {
  TumDatasetOptions options;
  EXPECT_NO_THROW(options.Check());
  options.max_time_difference = 0;
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { options.Check(); }), "dataset.max_time_difference"));
  options.max_time_difference = NAN;
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { options.Check(); }), "dataset.max_time_difference"));
  options = {};
  options.depth_factor = -5000;
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { options.Check(); }),
                       "dataset.depth_factor must be >= 0 (PNG value per metre; 0: by the camera), got -5000"));
  options = {};
  options.camera.source = "custom";
  options.camera.custom.fx = 0;
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { options.Check(); }), "camera (source \"custom\")"));
}

TEST(TumDataset, LoadsAssociatedFramesWithDepthInMetres) {
  TempDir dir;
  TumTestFolderSpec spec;
  spec.frames = 3;
  const TumTestFolder seq = WriteTumTestFolder(dir, spec);
  const TumDataset dataset(seq.folder);
  ASSERT_EQ(dataset.size(), 3u);
  EXPECT_EQ(dataset.unmatched_rgb(), 0u);
  EXPECT_EQ(dataset.name(), "synthetic");
  EXPECT_EQ(dataset.folder(), seq.folder);
  EXPECT_FALSE(dataset.has_groundtruth());
  EXPECT_TRUE(dataset.groundtruth().empty());
  EXPECT_FALSE(dataset.has_masks());
  EXPECT_EQ(dataset.depth_factor(), 5000.0);
  for (size_t i = 0; i < dataset.size(); ++i) {
    EXPECT_EQ(dataset.stamp(i), seq.rgb_stamps[i]);
    const RgbdFrame frame = dataset.Load(i);
    EXPECT_EQ(frame.index, i);
    EXPECT_EQ(frame.stamp, seq.rgb_stamps[i]);
    EXPECT_EQ(frame.depth_stamp, seq.depth_stamps[i]);
    ASSERT_EQ(frame.bgr.type(), CV_8UC3);
    ASSERT_EQ(frame.gray.type(), CV_8UC1);
    ASSERT_EQ(frame.depth.type(), CV_32FC1);
    EXPECT_EQ(frame.bgr.size(), cv::Size(640, 480));
    EXPECT_EQ(frame.bgr.at<cv::Vec3b>(7, 300), cv::Vec3b(300 % 256, 7, 10 * i));
    // Gray is the BT.601 luma of the BGR pixel (OpenCV's 0.299 R + 0.587 G + 0.114 B).
    const cv::Vec3b bgr = frame.bgr.at<cv::Vec3b>(200, 100);
    EXPECT_NEAR(frame.gray.at<uchar>(200, 100), 0.114 * bgr[0] + 0.587 * bgr[1] + 0.299 * bgr[2], 0.51);
    // PNG 5000 (1 + i) -> 1 + i metres; 0 stays 0 (no data); 12345 -> 2.469 m.
    EXPECT_FLOAT_EQ(frame.depth.at<float>(100, 100), 1.0f + i);
    EXPECT_EQ(frame.depth.at<float>(100, 0), 0.0f);
    EXPECT_FLOAT_EQ(frame.depth.at<float>(1, 1), 2.469f);
  }
  EXPECT_THROW(dataset.Load(3), std::out_of_range);
}

TEST(TumDataset, DepthFactorFromOptionsElseCameraFile) {
  TempDir dir;
  const TumTestFolder seq = WriteTumTestFolder(dir, {});
  EXPECT_EQ(TumDataset(seq.folder).depth_factor_origin(), "default (5000)");
  WriteCameraFile(seq.folder + "/camera.json", Camera(), 10000.0);
  const TumDataset from_file(seq.folder);
  EXPECT_EQ(from_file.depth_factor(), 10000.0);
  EXPECT_FLOAT_EQ(from_file.Load(0).depth.at<float>(5, 5), 0.5f);
  EXPECT_EQ(from_file.depth_factor_origin(), "camera.json (" + seq.folder + "/camera.json)");
  // The config's value is the user's last word: it wins over the file.
  TumDatasetOptions options;
  options.depth_factor = 1000;
  const TumDataset from_options(seq.folder, options);
  EXPECT_FLOAT_EQ(from_options.Load(0).depth.at<float>(5, 5), 5.0f);
  EXPECT_EQ(from_options.depth_factor_origin(), "config: dataset.depth_factor");
}

TEST(TumDataset, DepthFactorByFolderNameWhenNotGiven) {
  TempDir dir;
  TumTestFolderSpec spec;
  spec.camera_json = false;
  spec.name = "rgbd_dataset_freiburg2_desk";
  const TumTestFolder fr2 = WriteTumTestFolder(dir, spec);
  spec.name = "rgbd_dataset_freiburg1_desk";
  const TumTestFolder fr1 = WriteTumTestFolder(dir, spec);
  EXPECT_EQ(TumDataset(fr2.folder, {}).depth_factor(), 5208.0);  // the fr2 Kinect's correction
  EXPECT_FLOAT_EQ(TumDataset(fr2.folder, {}).Load(0).depth.at<float>(240, 320), static_cast<float>(5000.0 / 5208.0));
  EXPECT_EQ(TumDataset(fr1.folder, {}).depth_factor(), 5000.0);
  TumDatasetOptions options;
  options.depth_factor = 5000;  // given: wins over the name
  EXPECT_EQ(TumDataset(fr2.folder, options).depth_factor(), 5000.0);
}

TEST(TumDataset, AssociationHonoursMaxTimeDifference) {
  TempDir dir;
  TumTestFolderSpec spec;
  spec.frames = 4;
  spec.depth_offset = 0.015;
  const TumTestFolder seq = WriteTumTestFolder(dir, spec);
  EXPECT_EQ(TumDataset(seq.folder).size(), 4u);
  TumDatasetOptions options;
  options.max_time_difference = 0.01;
  const std::string message = test::InputErrorOf([&] { TumDataset(seq.folder, options); });
  EXPECT_TRUE(Contains(message, seq.folder + "/rgb.txt")) << message;
  EXPECT_TRUE(Contains(message, "dataset.max_time_difference")) << message;

  // Without depth for frame 1, that RGB frame is dropped and counted.
  test::WriteList(seq.folder, "depth.txt", {seq.depth_stamps[0], seq.depth_stamps[2], seq.depth_stamps[3]},
                  {seq.depth_files[0], seq.depth_files[2], seq.depth_files[3]});
  const TumDataset dataset(seq.folder);
  ASSERT_EQ(dataset.size(), 3u);
  EXPECT_EQ(dataset.unmatched_rgb(), 1u);
  EXPECT_EQ(dataset.stamp(1), seq.rgb_stamps[2]);
  EXPECT_EQ(dataset.Load(1).depth_stamp, seq.depth_stamps[2]);
}

TEST(TumDataset, ListsWithCommentsCrlfAndExtraSpaces) {
  TempDir dir;
  const TumTestFolder seq = WriteTumTestFolder(dir, {});
  std::string rgb = "# color images\r\n\r\n";
  for (size_t i = 0; i < seq.rgb_files.size(); ++i)
    rgb += "  " + std::to_string(seq.rgb_stamps[i]) + "\t " + seq.rgb_files[i] + "  \r\n";
  dir.Write("synthetic/rgb.txt", rgb);
  EXPECT_EQ(TumDataset(seq.folder).size(), seq.rgb_files.size());
}

TEST(TumDataset, FolderAndListErrorsNameThePath) {
  TempDir dir;
  const std::string missing = (dir.path() / "nowhere").string();
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { TumDataset{missing}; }), missing + ": no such folder"));

  const TumTestFolder seq = WriteTumTestFolder(dir, {});
  std::filesystem::remove(seq.folder + "/depth.txt");
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { TumDataset{seq.folder}; }), seq.folder + "/depth.txt: missing file"));
  std::filesystem::remove(seq.folder + "/rgb.txt");
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { TumDataset{seq.folder}; }), seq.folder + "/rgb.txt: missing file"));
}

TEST(TumDataset, BadListLinesNameFileAndLine) {
  TempDir dir;
  const TumTestFolder seq = WriteTumTestFolder(dir, {});
  // WriteList puts two comment lines first: data lines are 3, 4, 5.
  test::WriteList(seq.folder, "depth.txt", {seq.depth_stamps[0], seq.depth_stamps[2], seq.depth_stamps[1]},
                  {seq.depth_files[0], seq.depth_files[2], seq.depth_files[1]});
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { TumDataset{seq.folder}; }),
                       seq.folder + "/depth.txt:5: timestamps must strictly increase"));
  dir.Write("synthetic/rgb.txt", "# c\n100.0 rgb/a.png\n100.1\n");
  EXPECT_TRUE(
      Contains(test::InputErrorOf([&] { TumDataset{seq.folder}; }), seq.folder + "/rgb.txt:3: expected 2 columns"));
  dir.Write("synthetic/groundtruth.txt", "1 0 0 0 0 0 0 1\n2 0 0 0 0 0 0\n");
  test::WriteList(seq.folder, "rgb.txt", seq.rgb_stamps, seq.rgb_files);
  test::WriteList(seq.folder, "depth.txt", seq.depth_stamps, seq.depth_files);
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { TumDataset{seq.folder}; }), seq.folder + "/groundtruth.txt:2:"));
  dir.Write("synthetic/groundtruth.txt", "# gt\n1 0 0 0 0 0 0 1\n2 0.5 0 0 0 0 0 1\n");
  const TumDataset dataset(seq.folder);
  EXPECT_TRUE(dataset.has_groundtruth());
  ASSERT_EQ(dataset.groundtruth().size(), 2u);
  EXPECT_EQ(dataset.groundtruth()[1].world_from_camera.translation().x(), 0.5);
}

TEST(TumDataset, ImageErrorsNameThePng) {
  TempDir dir;
  TumTestFolderSpec spec;
  spec.frames = 6;
  const TumTestFolder seq = WriteTumTestFolder(dir, spec);
  const auto png = [&](const std::string& file) { return seq.folder + "/" + file; };
  std::filesystem::remove(png(seq.rgb_files[0]));
  test::WriteImage(png(seq.depth_files[1]), cv::Mat(480, 640, CV_8UC1, cv::Scalar(3)));
  test::WriteImage(png(seq.rgb_files[2]), cv::Mat(240, 320, CV_8UC3, cv::Scalar(1, 2, 3)));
  test::WriteImage(png(seq.rgb_files[3]), cv::Mat(480, 640, CV_16UC3, cv::Scalar(1, 2, 3)));
  dir.Write("synthetic/" + seq.depth_files[4], "not a png");
  test::WriteImage(png(seq.depth_files[5]), cv::Mat(480, 641, CV_16UC1, cv::Scalar(3)));
  const TumDataset dataset(seq.folder);  // images are read by Load, not by the constructor
  std::string message = test::InputErrorOf([&] { dataset.Load(0); });
  EXPECT_TRUE(Contains(message, png(seq.rgb_files[0]) + ": missing image")) << message;
  EXPECT_TRUE(Contains(message, seq.folder + "/rgb.txt:3")) << message;
  message = test::InputErrorOf([&] { dataset.Load(1); });
  EXPECT_TRUE(
      Contains(message, png(seq.depth_files[1]) + ": depth image must be 16-bit 1-channel, got 8-bit 1-channel"))
      << message;
  message = test::InputErrorOf([&] { dataset.Load(2); });
  EXPECT_TRUE(Contains(message, png(seq.rgb_files[2]) + ": image is 320x240, the camera is 640x480")) << message;
  message = test::InputErrorOf([&] { dataset.Load(3); });
  EXPECT_TRUE(Contains(message, png(seq.rgb_files[3]) + ": RGB image must be 8-bit")) << message;
  message = test::InputErrorOf([&] { dataset.Load(4); });
  EXPECT_TRUE(Contains(message, png(seq.depth_files[4]) + ": cannot decode image")) << message;
  message = test::InputErrorOf([&] { dataset.Load(5); });
  EXPECT_TRUE(Contains(message, png(seq.depth_files[5]) + ": image is 641x480")) << message;
}

TEST(TumDataset, AnImageNameTooLongIsAnInputErrorNamingIt) {
  TempDir dir;
  TumTestFolderSpec spec;
  spec.frames = 2;
  const TumTestFolder seq = WriteTumTestFolder(dir, spec);
  const std::string long_name = "rgb/" + std::string(300, 'a') + ".png";  // beyond NAME_MAX (255)
  test::WriteList(seq.folder, "rgb.txt", seq.rgb_stamps, {seq.rgb_files[0], long_name});
  const TumDataset dataset(seq.folder);
  EXPECT_NO_THROW(dataset.Load(0));
  const std::string error = test::InputErrorOf([&] { dataset.Load(1); });
  EXPECT_EQ(error.rfind(seq.folder + "/" + long_name + ": cannot examine: File name too long", 0), 0u) << error;
  EXPECT_TRUE(Contains(error, "rgb.txt:")) << error;
}

TEST(TumDataset, AcceptsGrayAndBgraRgbImages) {
  TempDir dir;
  TumTestFolderSpec spec;
  spec.frames = 2;
  const TumTestFolder seq = WriteTumTestFolder(dir, spec);
  test::WriteImage(seq.folder + "/" + seq.rgb_files[0], cv::Mat(480, 640, CV_8UC1, cv::Scalar(77)));
  test::WriteImage(seq.folder + "/" + seq.rgb_files[1], cv::Mat(480, 640, CV_8UC4, cv::Scalar(10, 20, 30, 128)));
  const TumDataset dataset(seq.folder);
  RgbdFrame frame = dataset.Load(0);
  EXPECT_EQ(frame.bgr.type(), CV_8UC3);
  EXPECT_EQ(frame.bgr.at<cv::Vec3b>(10, 10), cv::Vec3b(77, 77, 77));
  EXPECT_EQ(frame.gray.at<uchar>(10, 10), 77);
  frame = dataset.Load(1);
  EXPECT_EQ(frame.bgr.type(), CV_8UC3);
  EXPECT_EQ(frame.bgr.at<cv::Vec3b>(10, 10), cv::Vec3b(10, 20, 30));
}

TEST(TumDataset, CameraPrecedenceConfigThenFileThenName) {
  TempDir dir;
  TumTestFolderSpec spec;
  spec.name = "rgbd_dataset_freiburg3_walking_xyz";
  spec.camera_json = false;
  spec.frames = 1;
  const TumTestFolder seq = WriteTumTestFolder(dir, spec);
  TumDatasetOptions no_undistort;
  no_undistort.undistort = false;
  const TumDataset from_name(seq.folder);
  EXPECT_EQ(from_name.camera().fx, 535.4);
  EXPECT_EQ(from_name.camera_origin(), "folder name: TUM RGB-D freiburg3 Kinect (camera.source \"fr3\")");

  Camera file_camera;
  file_camera.fx = 600;
  file_camera.distortion = {0.01, 0, 0, 0, 0};
  WriteCameraFile(seq.folder + "/camera.json", file_camera);
  const TumDataset from_file(seq.folder, no_undistort);
  EXPECT_EQ(from_file.camera().fx, 600.0);
  EXPECT_EQ(from_file.camera().distortion, file_camera.distortion);
  EXPECT_EQ(from_file.depth_factor(), 5000.0);
  EXPECT_EQ(from_file.camera_origin(), "camera.json (" + seq.folder + "/camera.json)");

  TumDatasetOptions custom;
  custom.camera.source = "custom";
  custom.camera.custom.fx = 700;
  const TumDataset from_config(seq.folder, custom);
  EXPECT_EQ(from_config.camera().fx, 700.0);
  EXPECT_FALSE(from_config.raw_camera().HasDistortion());
  EXPECT_EQ(from_config.camera_origin(), "config: camera.source \"custom\" and camera.*");
  TumDatasetOptions named;
  named.camera.source = "fr2";
  const TumDataset from_named(seq.folder, named);
  EXPECT_EQ(from_named.raw_camera().fx, 520.9);
  EXPECT_EQ(from_named.depth_factor(), 5208.0);

  dir.Write(spec.name + "/camera.json", R"({"width":640,"height":480,"fx":500})");
  EXPECT_TRUE(
      Contains(test::InputErrorOf([&] { TumDataset{seq.folder}; }), seq.folder + "/camera.json: missing key 'fy'"));

  // A trailing separator does not change the name, hence the camera.
  std::filesystem::remove(seq.folder + "/camera.json");
  const TumDataset trailing(seq.folder + "/");
  EXPECT_EQ(trailing.name(), spec.name);
  EXPECT_EQ(trailing.camera().fx, 535.4);
}

TEST(TumDataset, AFolderWhoseCameraCannotBeToldIsAnErrorThatSaysHowToGiveIt) {
  TempDir dir;
  TumTestFolderSpec spec;
  spec.name = "my_office_walk";
  spec.camera_json = false;
  spec.frames = 1;
  const TumTestFolder seq = WriteTumTestFolder(dir, spec);
  const std::string error = test::InputErrorOf([&] { TumDataset{seq.folder}; });
  EXPECT_EQ(error.rfind(seq.folder + ": cannot tell its camera", 0), 0u) << error;
  for (const char* way : {"camera.json", "--set camera.source=custom", "ros_default"})
    EXPECT_TRUE(Contains(error, way)) << way << " missing from: " << error;
  // The ROS default only when asked for by name, and run.json's origin says so.
  TumDatasetOptions ros;
  ros.camera.source = "ros_default";
  const TumDataset explicit_default(seq.folder, ros);
  EXPECT_EQ(explicit_default.camera().fx, 525.0);
  EXPECT_EQ(explicit_default.camera_origin(), "config: camera.source \"ros_default\" (ROS default pinhole)");
  // Intrinsics given while the source would ignore them are refused, naming the key.
  TumDatasetOptions ignored;
  ignored.camera.custom.fx = 600;
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { TumDataset(seq.folder, ignored); }),
                       "camera.fx is set but camera.source is \"auto\""));
}

TEST(TumDataset, BonnFoldersReadWithBonnsCamera) {
  TempDir dir;
  TumTestFolderSpec spec;
  spec.name = "rgbd_bonn_balloon";
  spec.camera_json = false;
  spec.frames = 1;
  const TumTestFolder seq = WriteTumTestFolder(dir, spec);
  const TumDataset bonn(seq.folder);
  EXPECT_EQ(bonn.raw_camera().fx, 542.822841);
  EXPECT_EQ(bonn.depth_factor(), 5000.0);
  EXPECT_FALSE(bonn.camera().HasDistortion());  // undistorted on load
  EXPECT_EQ(bonn.depth_factor_origin(), "folder name: Bonn RGB-D Dynamic Xtion");
}

TEST(TumDataset, CameraWithoutDistortionLeavesImagesByteIdentical) {
  TempDir dir;
  TumTestFolderSpec spec;
  spec.frames = 1;
  const TumTestFolder seq = WriteTumTestFolder(dir, spec);
  cv::Mat depth_png = test::TestDepth(640, 480, 0);
  cv::randu(depth_png, 0, 60000);
  test::WriteImage(seq.folder + "/" + seq.depth_files[0], depth_png);
  const TumDataset dataset(seq.folder);
  EXPECT_FALSE(dataset.raw_camera().HasDistortion());
  const RgbdFrame frame = dataset.Load(0);
  const cv::Mat expected_bgr = test::TestBgr(640, 480, 0);
  EXPECT_EQ(cv::norm(frame.bgr, expected_bgr, cv::NORM_INF), 0.0);
  // Depth is the PNG value / 5000 exactly: values up to 60000 times 5000 round back.
  cv::Mat back;
  frame.depth.convertTo(back, CV_32F, 5000.0);
  cv::Mat rounded;
  back.convertTo(rounded, CV_16U);
  EXPECT_EQ(cv::norm(rounded, depth_png, cv::NORM_INF), 0.0);
  EXPECT_EQ(dataset.camera().fx, dataset.raw_camera().fx);
}

// The distorted pixel at which the sensor sees what an ideal pinhole camera sees at
// `undistorted`, computed with cv::projectPoints (not with the undistortion maps).
cv::Point2d DistortedPixel(const Camera& camera, cv::Point2d undistorted) {
  const std::vector<cv::Point3d> ray = {
      {(undistorted.x - camera.cx) / camera.fx, (undistorted.y - camera.cy) / camera.fy, 1.0}};
  std::vector<cv::Point2d> pixel;
  cv::projectPoints(ray, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), camera.K(), camera.DistCoeffs(), pixel);
  return pixel[0];
}

TEST(TumDataset, UndistortionMovesPixelsWherePredicted) {
  TempDir dir;
  TumTestFolderSpec spec;
  spec.name = "rgbd_dataset_freiburg1_synthetic";
  spec.camera_json = false;
  spec.frames = 1;
  const TumTestFolder seq = WriteTumTestFolder(dir, spec);
  const Camera fr1 = KnownCameraForFolder(spec.name)->camera;
  const cv::Point target(60, 50);  // near a corner, where fr1's distortion is large
  const cv::Point2d source = DistortedPixel(fr1, target);
  const cv::Point source_px(static_cast<int>(std::lround(source.x)), static_cast<int>(std::lround(source.y)));
  ASSERT_GT(cv::norm(source - cv::Point2d(target)), 5.0) << "distortion too small to test";

  // A 5x5 white square in RGB, a 3x3 block of 2 m in depth and mask, centred at the
  // distorted position; elsewhere black, 1 m, unmasked.
  cv::Mat rgb(480, 640, CV_8UC3, cv::Scalar::all(0));
  cv::rectangle(rgb, cv::Rect(source_px.x - 2, source_px.y - 2, 5, 5), cv::Scalar::all(255), cv::FILLED);
  cv::Mat depth(480, 640, CV_16UC1, cv::Scalar(5000));
  depth(cv::Rect(source_px.x - 1, source_px.y - 1, 3, 3)).setTo(10000);
  cv::Mat mask(480, 640, CV_8UC1, cv::Scalar(0));
  mask(cv::Rect(source_px.x - 1, source_px.y - 1, 3, 3)).setTo(1);
  test::WriteImage(seq.folder + "/" + seq.rgb_files[0], rgb);
  test::WriteImage(seq.folder + "/" + seq.depth_files[0], depth);
  test::WriteImage(seq.folder + "/masks/0.png", mask);
  test::WriteList(seq.folder, "masks.txt", {seq.rgb_stamps[0]}, {"masks/0.png"});

  const TumDataset dataset(seq.folder);
  EXPECT_TRUE(dataset.raw_camera().HasDistortion());
  EXPECT_FALSE(dataset.camera().HasDistortion());
  EXPECT_EQ(dataset.camera().fx, fr1.fx);
  EXPECT_EQ(dataset.camera().cx, fr1.cx);
  const RgbdFrame frame = dataset.Load(0);
  const cv::Mat frame_mask = dataset.LoadMask(0);
  // The square's centre lands on the target: bilinear samples within half a pixel of it
  // stay inside the 5x5 square.
  EXPECT_EQ(frame.gray.at<uchar>(target), 255);
  EXPECT_FLOAT_EQ(frame.depth.at<float>(target), 2.0f);
  EXPECT_EQ(frame_mask.at<uchar>(target), 255);
  // And it is no longer where it was in the raw image.
  EXPECT_EQ(frame.gray.at<uchar>(source_px), 0);
  EXPECT_FLOAT_EQ(frame.depth.at<float>(source_px), 1.0f);
  EXPECT_EQ(frame_mask.at<uchar>(source_px), 0);
  // Nearest sampling: depth holds only the two written values or 0 (outside the sensor).
  for (int y = 0; y < 480; ++y)
    for (int x = 0; x < 640; ++x) {
      const float d = frame.depth.at<float>(y, x);
      ASSERT_TRUE(d == 0.0f || d == 1.0f || d == 2.0f) << d << " at " << x << "," << y;
    }
  EXPECT_EQ(cv::countNonZero(frame_mask == 255) + cv::countNonZero(frame_mask == 0), 640 * 480);

  // The image area excludes the border the remap leaves without sensor pixels.
  const ImageArea& area = dataset.image_area();
  ASSERT_GE(area.size(), 3u);
  const cv::Mat inside = AreaMask(area, frame.gray.size());
  EXPECT_LT(cv::countNonZero(inside), 640 * 480 - 1000) << "fr1's border is thicker than that";
  EXPECT_GT(cv::countNonZero(inside), 640 * 480 * 9 / 10);
  EXPECT_EQ(inside.at<uchar>(240, 320), 255);
  EXPECT_EQ(inside.at<uchar>(0, 0), 0);
  EXPECT_EQ(frame.depth.at<float>(0, 0), 0.0f);  // no sensor pixel maps to the corner
  cv::Mat zero_depth_inside;
  cv::bitwise_and(inside, frame.depth == 0.0f, zero_depth_inside);
  EXPECT_EQ(cv::countNonZero(zero_depth_inside), 0);  // depth (1 m everywhere) is defined inside

  // With undistortion off, images are as stored and the camera keeps its distortion.
  TumDatasetOptions raw;
  raw.undistort = false;
  const TumDataset raw_dataset(seq.folder, raw);
  EXPECT_TRUE(raw_dataset.camera().HasDistortion());
  EXPECT_TRUE(raw_dataset.image_area().empty());
  EXPECT_EQ(raw_dataset.Load(0).gray.at<uchar>(source_px), 255);
  EXPECT_EQ(raw_dataset.LoadMask(0).at<uchar>(source_px), 255);
}

TEST(TumDataset, MasksByRgbStamp) {
  TempDir dir;
  TumTestFolderSpec spec;
  spec.frames = 3;
  const TumTestFolder seq = WriteTumTestFolder(dir, spec);
  EXPECT_TRUE(Contains(test::InputErrorOf([&] { TumDataset(seq.folder).LoadMask(0); }),
                       seq.folder + "/masks.txt: missing file"));

  cv::Mat mask(480, 640, CV_8UC1, cv::Scalar(0));
  mask(cv::Rect(10, 20, 30, 40)).setTo(255);
  test::WriteImage(seq.folder + "/masks/a.png", mask);
  test::WriteImage(seq.folder + "/masks/c.png", cv::Mat(480, 640, CV_8UC3, cv::Scalar::all(0)));
  test::WriteList(seq.folder, "masks.txt", {seq.rgb_stamps[0], seq.rgb_stamps[2]}, {"masks/a.png", "masks/c.png"});
  const TumDataset dataset(seq.folder);
  EXPECT_TRUE(dataset.has_masks());
  const cv::Mat loaded = dataset.LoadMask(0);
  ASSERT_EQ(loaded.type(), CV_8UC1);
  EXPECT_EQ(cv::norm(loaded, mask, cv::NORM_INF), 0.0);
  // A generated sequence's still people: dynamic for LoadMask, their own value for LoadMaskLabels.
  cv::Mat labelled = mask.clone();
  labelled(cv::Rect(10, 20, 5, 40)).setTo(kStillPersonLabel);
  test::WriteImage(seq.folder + "/masks/a.png", labelled);
  EXPECT_EQ(cv::norm(dataset.LoadMask(0), mask, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(dataset.LoadMaskLabels(0), labelled, cv::NORM_INF), 0.0);
  std::string message = test::InputErrorOf([&] { dataset.LoadMask(1); });
  EXPECT_TRUE(Contains(message, seq.folder + "/masks.txt: no mask entry")) << message;
  EXPECT_TRUE(Contains(message, seq.folder + "/rgb.txt:4")) << message;
  message = test::InputErrorOf([&] { dataset.LoadMask(2); });
  EXPECT_TRUE(Contains(message, seq.folder + "/masks/c.png: mask must be 8-bit 1-channel")) << message;
}

}  // namespace
}  // namespace dynvo
