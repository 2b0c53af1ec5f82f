#include "odometry/odometry_config.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/temp_dir.h"

namespace dynvo {
namespace {

std::string ConfigPath(const std::string& name) {
  return std::string(DYNVO_SOURCE_DIR) + "/configs/" + name;
}

std::string LoadError(const std::string& path, const std::vector<std::string>& overrides) {
  try {
    LoadOdometryConfig(path, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(OdometryConfig, PaperConfigHasThePapersParameters) {
  const OdometryConfig c = LoadOdometryConfig(ConfigPath("paper.json"), {});
  EXPECT_TRUE(c.dynamic_mask_enabled);
  EXPECT_EQ(c.dynamic_mask.threshold, ThresholdMethod::kOtsu);
  EXPECT_EQ(c.dynamic_mask.erode_kernel_size, 4);
  EXPECT_EQ(c.dynamic_mask.erode_iterations, 2);
  EXPECT_EQ(c.dynamic_mask.dilate_kernel_size, 16);
  EXPECT_EQ(c.dynamic_mask.dilate_iterations, 1);
  EXPECT_NE(c.dynamic_mask.backward, BackwardMode::kNone);
}

TEST(OdometryConfig, BaselineDiffersOnlyByTheDynamicHandling) {
  nlohmann::json paper = OdometryConfigToJson(LoadOdometryConfig(ConfigPath("paper.json"), {}));
  nlohmann::json baseline = OdometryConfigToJson(LoadOdometryConfig(ConfigPath("baseline.json"), {}));
  EXPECT_EQ(baseline["dynamic_mask"]["enabled"], false);
  // The dynamic handling: the mask stage, and new map points confirmed before they are trusted.
  EXPECT_GT(paper["tracking"]["new_point_confirmations"], 0);
  EXPECT_EQ(baseline["tracking"]["new_point_confirmations"], 0);
  paper["tracking"].erase("new_point_confirmations");
  baseline["tracking"].erase("new_point_confirmations");
  // Mask parameters are irrelevant when the stage is off; all other stages must be identical.
  paper.erase("dynamic_mask");
  baseline.erase("dynamic_mask");
  EXPECT_EQ(paper, baseline) << nlohmann::json::diff(paper, baseline).dump(1);
}

TEST(OdometryConfig, OcclusionIsPaperWithTheAdditions) {
  const nlohmann::json occlusion = OdometryConfigToJson(LoadOdometryConfig(ConfigPath("occlusion.json"), {}));
  const nlohmann::json paper_with_additions = OdometryConfigToJson(LoadOdometryConfig(
      ConfigPath("paper.json"),
      {"map_occlusion.enabled=true", "map_occlusion.grow_px=20", "map_occlusion.seeded=true",
       "depth_change.enabled=true", "depth_change.seeds_only=true", "features.refill_outside_mask=true",
       "features.refill_from_background=true", "depth_trim.enabled=true",
       "tracking.coherent_motion.enabled=true", "features.refill_reuse_corners=true",
       "dynamic_mask.difference_level=1"}));
  EXPECT_EQ(occlusion, paper_with_additions) << nlohmann::json::diff(paper_with_additions, occlusion).dump(1);
}

TEST(OdometryConfig, ErrorsNameFileAndKey) {
  test::TempDir dir;
  const std::string bad_key = dir.Write("bad_key.json", R"({"dynamic_mask": {"erode_iterationz": 2}})");
  EXPECT_NE(LoadError(bad_key, {}).find("bad_key.json: unknown key 'dynamic_mask.erode_iterationz'"),
            std::string::npos);
  const std::string not_json = dir.Write("broken.json", "{\"features\": ");
  EXPECT_NE(LoadError(not_json, {}).find("broken.json: not valid JSON"), std::string::npos);
  EXPECT_NE(LoadError(dir.path().string() + "/missing.json", {}).find("missing.json: cannot open"),
            std::string::npos);
  const std::string range = LoadError("", {"dynamic_mask.erode_iterations=-1"});
  EXPECT_NE(range.find("dynamic_mask.erode_iterations"), std::string::npos) << range;
  const std::string coherent = LoadError("", {"tracking.coherent_motion.min_z=0"});
  EXPECT_NE(coherent.find("tracking.coherent_motion.min_z must be > 0"), std::string::npos) << coherent;
  const std::string features = LoadError("", {"features.num_features=0"});
  EXPECT_NE(features.find("features.num_features"), std::string::npos) << features;
  EXPECT_NE(LoadError("", {"dynamic_mask.backward=sideways"}).find("dynamic_mask.backward"),
            std::string::npos);
  const std::string source = LoadError("", {"dynamic_mask.source=oracle"});
  EXPECT_NE(source.find("dynamic_mask.source"), std::string::npos) << source;
  EXPECT_NE(source.find("ground_truth"), std::string::npos) << source;
}

TEST(OdometryConfig, OverridesWinOverTheFile) {
  const OdometryConfig c = LoadOdometryConfig(
      ConfigPath("paper.json"), {"dynamic_mask.dilate_kernel_size=9", "dynamic_mask.backward=triplet",
                                 "camera.source=fr1", "dynamic_mask.source=ground_truth"});
  EXPECT_EQ(LoadOdometryConfig(ConfigPath("paper.json"), {}).dynamic_mask_source, MaskSourceKind::kDifference);
  EXPECT_EQ(c.dynamic_mask_source, MaskSourceKind::kGroundTruth);
  EXPECT_EQ(c.dynamic_mask.dilate_kernel_size, 9);
  EXPECT_EQ(c.dynamic_mask.backward, BackwardMode::kTriplet);
  ASSERT_TRUE(c.CameraOverride().has_value());
  EXPECT_DOUBLE_EQ(c.CameraOverride()->fx, 517.3);
}

// `enabled_key`=true is accepted with paper.json, and refused with the baseline (naming the file
// and the key) and with the ground-truth masks: each mask addition needs the detector's mask.
void ExpectNeedsTheDetector(const std::string& enabled_key) {
  const std::string on = enabled_key + "=true";
  EXPECT_NO_THROW(LoadOdometryConfig(ConfigPath("paper.json"), {on}));
  try {
    LoadOdometryConfig(ConfigPath("baseline.json"), {on});
    ADD_FAILURE() << enabled_key << ": the baseline has no mask to add to";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), ConfigPath("baseline.json") + ": " + enabled_key +
                                          " needs dynamic_mask.enabled (the baseline has no mask)");
  }
  EXPECT_THROW(LoadOdometryConfig(ConfigPath("paper.json"), {on, "dynamic_mask.source=ground_truth"}), InputError)
      << enabled_key;
}

TEST(OdometryConfig, MaskAdditionsNeedTheDetector) {
  ExpectNeedsTheDetector("depth_change.enabled");
  ExpectNeedsTheDetector("map_occlusion.enabled");
  EXPECT_THROW(LoadOdometryConfig("", {"depth_change.frames=11"}), InputError);
  EXPECT_THROW(LoadOdometryConfig("", {"map_occlusion.grow_px=65"}), InputError);
}

TEST(OdometryConfig, DepthTrimNeedsTheMapOcclusion) {
  EXPECT_NO_THROW(
      LoadOdometryConfig(ConfigPath("paper.json"), {"map_occlusion.enabled=true", "depth_trim.enabled=true"}));
  try {
    LoadOdometryConfig(ConfigPath("paper.json"), {"depth_trim.enabled=true"});
    ADD_FAILURE() << "without the map occlusion nothing says what the map explains";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              ConfigPath("paper.json") +
                  ": depth_trim.enabled needs map_occlusion.enabled (only what the static map explains is trimmed)");
  }
  EXPECT_THROW(LoadOdometryConfig(ConfigPath("baseline.json"), {"depth_trim.enabled=true"}), InputError);
  EXPECT_THROW(LoadOdometryConfig("", {"depth_trim.min_gap=-0.1"}), InputError);
  EXPECT_THROW(LoadOdometryConfig("", {"depth_trim.min_region_px=0"}), InputError);
  EXPECT_THROW(LoadOdometryConfig("", {"depth_trim.min_explained=1.5"}), InputError);
}

TEST(OdometryConfig, DepthChangeSeedsNeedTheSeededMapOcclusion) {
  const std::vector<std::string> seeded = {"map_occlusion.enabled=true", "map_occlusion.seeded=true"};
  const std::vector<std::string> change_seeds = {"depth_change.enabled=true", "depth_change.seeds_only=true"};
  std::vector<std::string> both = seeded;
  both.insert(both.end(), change_seeds.begin(), change_seeds.end());
  EXPECT_NO_THROW(LoadOdometryConfig(ConfigPath("paper.json"), both));
  try {
    LoadOdometryConfig(ConfigPath("paper.json"), change_seeds);
    ADD_FAILURE() << "without the seeded map occlusion there is nothing to seed";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              ConfigPath("paper.json") +
                  ": depth_change.seeds_only needs depth_change.enabled, map_occlusion.enabled and "
                  "map_occlusion.seeded (it only seeds the seeded map occlusion)");
  }
  // The depth change itself off: no seeds to give.
  std::vector<std::string> without_change = seeded;
  without_change.push_back("depth_change.seeds_only=true");
  EXPECT_THROW(LoadOdometryConfig(ConfigPath("paper.json"), without_change), InputError);
}

TEST(OdometryConfig, ReaderOptionsCarryTheDatasetKeysAndTheCamera) {
  const OdometryConfig c = LoadOdometryConfig("", {"camera.source=fr1", "dataset.depth_factor=1000"});
  const TumDatasetOptions options = c.ReaderOptions();
  EXPECT_DOUBLE_EQ(options.depth_factor, 1000.0);
  ASSERT_TRUE(options.camera.has_value());
  EXPECT_DOUBLE_EQ(options.camera->fx, 517.3);
  EXPECT_FALSE(LoadOdometryConfig("", {}).ReaderOptions().camera.has_value());  // "auto"
}

TEST(OdometryConfig, EchoReloadsToTheSameConfig) {
  const OdometryConfig c = LoadOdometryConfig(ConfigPath("paper.json"), {"features.num_features=700"});
  test::TempDir dir;
  const std::string echo = dir.Write("echo.json", OdometryConfigToJson(c).dump());
  EXPECT_EQ(OdometryConfigToJson(LoadOdometryConfig(echo, {})), OdometryConfigToJson(c));
  EXPECT_GT(DescribeConfigKeys().size(), 50u);
}

}  // namespace
}  // namespace dynvo
