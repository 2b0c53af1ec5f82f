#include "detection/detector_options.h"

#include <gtest/gtest.h>

#include "core/config_registry.h"
#include "core/error.h"

namespace dynvo {
namespace {

TEST(DetectorOptions, CheckNamesTheKey) {
  DetectorOptions options;
  EXPECT_NO_THROW(options.Check());
  options.input_size = 300;
  try {
    options.Check();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "detector.input_size must be a multiple of 32 in 64-1280, got 300");
  }
  options = {};
  options.confidence = 1.0;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.nms_threshold = 0.0;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.classes = {0, -1};
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.every_frames = 0;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.wait_ms = -1.0;
  EXPECT_THROW(options.Check(), InputError);
}

TEST(DetectorOptions, KeysAreTheStructPaths) {
  DetectorOptions options;
  ConfigRegistry registry;
  BindConfigKeys("detector", &options, &registry);
  registry.ApplyOverride("detector.classes=[0,2]");
  registry.ApplyOverride("detector.model=m.onnx");
  registry.ApplyOverride("detector.input_size=416");
  registry.ApplyOverride("detector.wait_ms=20");
  EXPECT_EQ(options.wait_ms, 20.0);
  EXPECT_EQ(options.classes, (std::vector<int>{0, 2}));
  EXPECT_EQ(options.model, "m.onnx");
  EXPECT_EQ(options.input_size, 416);
}

}  // namespace
}  // namespace dynvo
