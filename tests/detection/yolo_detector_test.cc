#include "detection/yolo_detector.h"

#include <fstream>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "core/error.h"
#include "support/shared_data.h"
#include "support/temp_dir.h"

namespace dynvo {
namespace {

// A Darknet region output: rows (cx, cy, w, h, objectness, class scores), relative coordinates.
TEST(DecodeYoloOutput, DarknetRowsMapToImagePixels) {
  cv::Mat rows = (cv::Mat_<float>(3, 7) << 0.5f, 0.5f, 0.2f, 0.6f, 0.9f, 0.8f, 0.1f,  // person, kept
                  0.2f, 0.3f, 0.1f, 0.1f, 0.9f, 0.1f, 0.7f,                           // class 1: not movable
                  0.8f, 0.8f, 0.1f, 0.1f, 0.3f, 0.3f, 0.0f);                          // below confidence
  const std::vector<Detection> found =
      DecodeYoloOutput(rows, YoloLayout::kDarknetRegion, cv::Size(640, 480), 320, DetectorOptions{});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].class_id, 0);
  EXPECT_NEAR(found[0].score, 0.8, 1e-6);
  EXPECT_NEAR(found[0].box.x, 256.0, 1e-3);  // (0.5 - 0.1) x 640
  EXPECT_NEAR(found[0].box.y, 96.0, 1e-3);   // (0.5 - 0.3) x 480
  EXPECT_NEAR(found[0].box.width, 128.0, 1e-3);
  EXPECT_NEAR(found[0].box.height, 288.0, 1e-3);
}

// YOLOv5 rows in input pixels with objectness, and YOLOv8 columns without: the same box.
TEST(DecodeYoloOutput, OnnxRowsAndColumnsAgree) {
  const int sizes[] = {1, 1, 7};
  cv::Mat v5(3, sizes, CV_32F);
  const float row[] = {160.f, 160.f, 64.f, 192.f, 0.9f, 0.9f, 0.05f};  // score 0.81
  std::copy(row, row + 7, v5.ptr<float>());
  const int column_sizes[] = {1, 6, 2};
  cv::Mat v8(3, column_sizes, CV_32F, cv::Scalar(0));
  float* c = v8.ptr<float>();  // 6 fields x 2 candidates; the second scores nothing
  const float first[] = {160.f, 160.f, 64.f, 192.f, 0.81f, 0.05f};
  for (int f = 0; f < 6; ++f) c[f * 2] = first[f];
  const DetectorOptions options;
  const std::vector<Detection> a = DecodeYoloOutput(v5, YoloLayout::kRows, cv::Size(640, 480), 320, options);
  const std::vector<Detection> b = DecodeYoloOutput(v8, YoloLayout::kColumns, cv::Size(640, 480), 320, options);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_NEAR(a[0].score, 0.81, 1e-6);
  EXPECT_NEAR(b[0].score, 0.81, 1e-6);
  EXPECT_NEAR(a[0].box.x, 256.0, 1e-3);  // (160 - 32) x 2
  EXPECT_NEAR(a[0].box.y, 96.0, 1e-3);   // (160 - 96) x 1.5
  EXPECT_NEAR((a[0].box & b[0].box).area(), a[0].box.area(), 1e-6);
}

TEST(SuppressOverlaps, KeepsTheBestOfOverlappingBoxesOfAClass) {
  const std::vector<Detection> candidates = {{cv::Rect2d(0, 0, 100, 200), 0.6, 0},
                                             {cv::Rect2d(5, 5, 100, 200), 0.9, 0},
                                             {cv::Rect2d(300, 0, 100, 200), 0.5, 0}};
  const std::vector<Detection> kept = SuppressOverlaps(candidates, DetectorOptions{});
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_DOUBLE_EQ(kept[0].score, 0.9);
  EXPECT_DOUBLE_EQ(kept[1].score, 0.5);
}

TEST(YoloDetector, MissingOrCorruptModelIsOneErrorNamingTheFile) {
  DetectorOptions options;
  options.model = "/nonexistent/yolo.weights";
  try {
    YoloDetector detector(options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "detector.model /nonexistent/yolo.weights: cannot open the file");
  }
  test::TempDir dir;
  const std::string corrupt = (dir.path() / "bad.onnx").string();
  std::ofstream(corrupt) << "not a network";
  options.model = corrupt;
  try {
    YoloDetector detector(options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("detector.model " + corrupt + ": OpenCV cannot load it", 0), 0u) << e.what();
  }
  options.model = (dir.path() / "model.bin").string();
  std::ofstream(options.model) << "x";
  EXPECT_THROW(YoloDetector{options}, InputError);
}

// The fr3_walking_xyz frame of the shared data shows two people; the body model finds both.
TEST(YoloDetector, FindsBothPeopleOfTheSharedSample) {
  DYNVO_REQUIRE_SHARED(shared);
  DetectorOptions options;
  options.config = shared + "/models/yolo-fastest-1.1_body.cfg";
  options.model = shared + "/models/yolo-fastest-1.1_body.weights";
  YoloDetector detector(options);
  const cv::Mat image = cv::imread(shared + "/data/samples/fr3_walking_xyz_rgb_1341846313.553992.png");
  ASSERT_FALSE(image.empty());
  const std::vector<Detection> people = detector.Detect(image);
  ASSERT_EQ(people.size(), 2u);
  for (const Detection& person : people) {
    EXPECT_GT(person.score, 0.6);
    EXPECT_GT(person.box.height, 0.3 * image.rows);  // people, not fragments
    EXPECT_GT(person.box.height, person.box.width);  // standing or sitting upright
  }
  EXPECT_LT((people[0].box & people[1].box).area(), 0.2 * std::min(people[0].box.area(), people[1].box.area()));
  EXPECT_EQ(detector.Detect(image).size(), 2u);  // the same answer again
}

}  // namespace
}  // namespace dynvo
