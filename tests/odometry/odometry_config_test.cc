#include "odometry/odometry_config.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/temp_dir.h"

namespace dynvo {
namespace {

std::string ConfigPath(const std::string& name) { return std::string(DYNVO_SOURCE_DIR) + "/configs/" + name; }

std::string LoadError(const std::string& path, const std::vector<std::string>& overrides) {
  try {
    LoadOdometryConfig(path, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(OdometryConfig, PaperConfigIsThePapersMethodLiterally) {
  const OdometryConfig c = LoadOdometryConfig(ConfigPath("paper.json"), {});
  EXPECT_EQ(c.mask_source, MaskSourceKind::kDifference);
  EXPECT_EQ(c.dynamic_mask.threshold, ThresholdMethod::kOtsu);
  EXPECT_EQ(c.dynamic_mask.min_otsu_threshold, 0);
  EXPECT_EQ(c.dynamic_mask.erode_kernel_size, 4);
  EXPECT_EQ(c.dynamic_mask.erode_iterations, 2);
  EXPECT_EQ(c.dynamic_mask.dilate_kernel_size, 16);
  EXPECT_EQ(c.dynamic_mask.dilate_iterations, 1);
  EXPECT_EQ(c.dynamic_mask.backward, BackwardMode::kReversePair);
  EXPECT_EQ(c.dynamic_mask.difference_level, 0);
  // None of the additions.
  EXPECT_FALSE(c.depth_change.enabled || c.map_occlusion.enabled || c.depth_trim.enabled);
  EXPECT_FALSE(c.features.refill_outside_mask || c.features.refill_from_background || c.features.refill_reuse_corners);
  EXPECT_EQ(c.tracking.readmit_masked_px, 0.0);
  EXPECT_EQ(c.tracking.new_point_confirmations, 0);
  EXPECT_FALSE(c.tracking.coherent_motion.enabled);
}

TEST(OdometryConfig, IplIsThePaperWithTheDetectorForItsMaskLinesAndOrbSlam2DepthWeight) {
  nlohmann::json paper = OdometryConfigToJson(LoadOdometryConfig(ConfigPath("paper.json"), {}));
  nlohmann::json ipl = OdometryConfigToJson(LoadOdometryConfig(ConfigPath("ipl.json"), {}));
  EXPECT_EQ(ipl["mask_source"], "detector");
  EXPECT_EQ(ipl["detector"]["model"], "data/models/yolo-fastest-1.1_body.weights");  // tools/fetch_models.sh
  EXPECT_EQ(ipl["features"]["lines"]["enabled"], true);  // the second paper's point-line tracking
  ipl["features"]["lines"]["enabled"] = false;
  EXPECT_EQ(ipl["local_ba"]["virtual_baseline_m"], 0.08);  // ORB-SLAM2's depth weight (bf 40), as the paper's
  ipl["local_ba"]["virtual_baseline_m"] = paper["local_ba"]["virtual_baseline_m"];
  for (const char* section : {"mask_source", "detector", "dynamic_mask"}) {  // dynamic_mask: the unused differencing
    paper.erase(section);
    ipl.erase(section);
  }
  EXPECT_EQ(paper, ipl) << nlohmann::json::diff(paper, ipl).dump(1);
  const std::string no_model = LoadError("", {"mask_source=detector", "detector.model=\"\""});
  EXPECT_NE(no_model.find("mask_source \"detector\" needs detector.model"), std::string::npos) << no_model;
}

TEST(OdometryConfig, BaselineIsThePaperWithoutItsMask) {
  nlohmann::json paper = OdometryConfigToJson(LoadOdometryConfig(ConfigPath("paper.json"), {}));
  nlohmann::json baseline = OdometryConfigToJson(LoadOdometryConfig(ConfigPath("baseline.json"), {}));
  EXPECT_EQ(paper["mask_source"], "difference");
  EXPECT_EQ(baseline["mask_source"], "none");
  // What only the mask uses is irrelevant without it; every other key must be the same.
  for (const char* section :
       {"mask_source", "dynamic_mask", "detector", "depth_change", "map_occlusion", "depth_trim"}) {
    paper.erase(section);
    baseline.erase(section);
  }
  for (const char* key : {"refill_outside_mask", "refill_from_background", "refill_reuse_corners"}) {
    paper["features"].erase(key);
    baseline["features"].erase(key);
  }
  EXPECT_EQ(paper, baseline) << nlohmann::json::diff(paper, baseline).dump(1);
}

TEST(OdometryConfig, TheDefaultsAreTheRecommendedConfig) {
  EXPECT_EQ(OdometryConfigToJson(LoadOdometryConfig("", {})),
            OdometryConfigToJson(LoadOdometryConfig(ConfigPath("dynvo.json"), {})));
  EXPECT_EQ(OdometryConfigToJson(OdometryConfig{}), OdometryConfigToJson(LoadOdometryConfig("", {})));
  const OdometryConfig c;
  EXPECT_TRUE(c.depth_change.enabled && c.map_occlusion.enabled && c.depth_trim.enabled);
  EXPECT_GT(c.tracking.new_point_confirmations, 0);
  EXPECT_EQ(c.detector.model, "data/models/yolo-fastest-1.1_body.weights");  // where tools/fetch_models.sh puts it
}

TEST(OdometryConfig, EveryKeyIsTheFieldsStructPath) {
  // A key's first part names a member of OdometryConfig (or is one), so `--set` reads like code.
  const std::vector<std::string> sections = {
      "dataset.",       "camera.",     "mask_source", "homography.", "dynamic_mask.", "detector.", "depth_change.",
      "map_occlusion.", "depth_trim.", "features.",   "tracking.",   "local_ba.",     "run."};
  for (const std::string& line : DescribeConfigKeys()) {
    bool known = false;
    for (const std::string& s : sections) known = known || line.rfind(s, 0) == 0;
    EXPECT_TRUE(known) << line;
  }
  OdometryConfig c = LoadOdometryConfig("", {"local_ba.window_keyframes=3", "tracking.pose.seed=11",
                                             "homography.seed=12", "tracking.matching.ratio=0.8"});
  EXPECT_EQ(c.local_ba.window_keyframes, 3);
  EXPECT_EQ(c.tracking.pose.seed, 11u);
  EXPECT_EQ(c.homography.seed, 12u);
  EXPECT_DOUBLE_EQ(c.tracking.matching.ratio, 0.8);
}

TEST(OdometryConfig, KeysOfEarlierVersionsSayWhatBecameOfThem) {
  const std::string moved = LoadError("", {"tracking.local_ba.enabled=false"});
  EXPECT_NE(moved.find("key 'tracking.local_ba.enabled' is now local_ba.enabled"), std::string::npos) << moved;
  const std::string source = LoadError("", {"dynamic_mask.enabled=false"});
  EXPECT_NE(source.find("is now mask_source"), std::string::npos) << source;
  const std::string retired = LoadError("", {"run.lookahead=false"});
  EXPECT_NE(retired.find("was retired"), std::string::npos) << retired;
  EXPECT_NE(retired.find("--threads 1"), std::string::npos) << retired;
}

TEST(OdometryConfig, ErrorsNameFileAndKey) {
  test::TempDir dir;
  const std::string bad_key = dir.Write("bad_key.json", R"({"dynamic_mask": {"erode_iterationz": 2}})");
  EXPECT_NE(LoadError(bad_key, {}).find("bad_key.json: unknown key 'dynamic_mask.erode_iterationz'"),
            std::string::npos);
  const std::string not_json = dir.Write("broken.json", "{\"features\": ");
  EXPECT_NE(LoadError(not_json, {}).find("broken.json: not valid JSON"), std::string::npos);
  EXPECT_NE(LoadError(dir.path().string() + "/missing.json", {}).find("missing.json: cannot open"), std::string::npos);
  const std::string range = LoadError("", {"dynamic_mask.erode_iterations=-1"});
  EXPECT_NE(range.find("dynamic_mask.erode_iterations"), std::string::npos) << range;
  const std::string window = LoadError("", {"local_ba.window_keyframes=0"});
  EXPECT_NE(window.find("local_ba.window_keyframes must be >= 1"), std::string::npos) << window;
  const std::string features = LoadError("", {"features.num_features=0"});
  EXPECT_NE(features.find("features.num_features"), std::string::npos) << features;
  EXPECT_NE(LoadError("", {"dynamic_mask.backward=sideways"}).find("dynamic_mask.backward"), std::string::npos);
  const std::string source = LoadError("", {"mask_source=oracle"});
  EXPECT_NE(source.find("mask_source"), std::string::npos) << source;
  EXPECT_NE(source.find("ground_truth"), std::string::npos) << source;
}

TEST(OdometryConfig, OverridesWinOverTheFile) {
  const OdometryConfig c = LoadOdometryConfig(ConfigPath("paper.json"),
                                              {"dynamic_mask.dilate_kernel_size=9", "dynamic_mask.backward=triplet",
                                               "camera.source=fr1", "mask_source=ground_truth"});
  EXPECT_EQ(LoadOdometryConfig(ConfigPath("paper.json"), {}).mask_source, MaskSourceKind::kDifference);
  EXPECT_EQ(c.mask_source, MaskSourceKind::kGroundTruth);
  EXPECT_EQ(c.dynamic_mask.dilate_kernel_size, 9);
  EXPECT_EQ(c.dynamic_mask.backward, BackwardMode::kTriplet);
  EXPECT_EQ(c.camera.source, "fr1");
}

TEST(OdometryConfig, TheDepthChangeAndTheTrimNeedTheMapOcclusion) {
  for (const std::string key : {"depth_change.enabled", "depth_trim.enabled"}) {
    EXPECT_NO_THROW(LoadOdometryConfig(ConfigPath("paper.json"), {"map_occlusion.enabled=true", key + "=true"}));
    const std::string error = LoadError(ConfigPath("paper.json"), {key + "=true"});
    EXPECT_EQ(error.rfind(ConfigPath("paper.json") + ": " + key + " needs map_occlusion.enabled", 0), 0u) << error;
  }
  // With another source than differencing they are not applied, and not refused: the recommended
  // config with the ground-truth masks or none.
  EXPECT_NO_THROW(LoadOdometryConfig("", {"mask_source=ground_truth"}));
  EXPECT_NO_THROW(LoadOdometryConfig("", {"mask_source=none"}));
  EXPECT_THROW(LoadOdometryConfig("", {"map_occlusion.grow_px=65"}), InputError);
}

TEST(OdometryConfig, ReaderOptionsCarryTheDatasetKeysAndTheCamera) {
  const OdometryConfig c = LoadOdometryConfig("", {"camera.source=fr1", "dataset.depth_factor=1000"});
  const TumDatasetOptions options = c.ReaderOptions();
  EXPECT_DOUBLE_EQ(options.depth_factor, 1000.0);
  EXPECT_EQ(options.camera.source, "fr1");
  EXPECT_EQ(LoadOdometryConfig("", {}).ReaderOptions().camera.source, "auto");
  const OdometryConfig custom = LoadOdometryConfig("", {"camera.source=custom", "camera.fx=600", "camera.k1=0.1"});
  EXPECT_EQ(custom.ReaderOptions().camera.custom.fx, 600.0);
  EXPECT_EQ(custom.ReaderOptions().camera.custom.distortion[0], 0.1);
  // Intrinsics the source would ignore are refused, naming the key; so is an unknown source.
  EXPECT_THROW(LoadOdometryConfig("", {"camera.fx=600"}), InputError);
  EXPECT_THROW(LoadOdometryConfig("", {"camera.source=fr4"}), InputError);
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
