// The tracker's scale on a turning camera: the generated loop path (a full turn in 15 s,
// looking outward from a 0.3 m circle; dynvo-synth --scenario none --camera-path loop
// --frames 300 --seed 5), static scene, baseline config. Turning while moving sideways is where
// the local BA can trade rotation for translation: with depth weighed as ORB-SLAM2 does (a
// virtual baseline of 0.08 m) the estimated path came out 6% too long here (Sim(3) scale 0.941);
// with the default weight its scale is 0.990.

#include <string>

#include <gtest/gtest.h>

#include "dataset/trajectory_io.h"
#include "dataset/tum_dataset.h"
#include "eval/ate.h"
#include "odometry/generated_sequence.h"
#include "odometry/sequence_runner.h"
#include "support/temp_dir.h"
#include "synth/synthetic_sequence.h"

namespace dynvo {
namespace {

TEST(TurningPathScale, LoopPathLengthWithinTwoAndAHalfPercent) {
  test::TempDir dir;
  SyntheticSequenceOptions options;
  options.scenario = Scenario::kNone;
  options.camera_path = CameraPathPreset::kLoop;
  options.frames = 300;
  options.seed = 5;
  const std::string sequence = test::WriteGeneratedSequence(options, dir.path() / "sequence");

  RunRequest request;
  request.dataset = sequence;
  request.config_path = std::string(DYNVO_SOURCE_DIR) + "/configs/baseline.json";
  request.out_dir = (dir.path() / "run").string();
  request.quiet = true;
  RunOdometry(request);

  AteOptions ate;
  ate.align = AteAlignment::kSim3;
  const AteResult result =
      ComputeAte(TumDataset(sequence).groundtruth(), ReadTrajectory(request.out_dir + "/trajectory.txt"), ate);
  // 2.5%: the default's 1% off plus margin for other CPUs; the old weight is 5.9% off.
  EXPECT_NEAR(result.alignment_scale, 1.0, 0.025);
}

}  // namespace
}  // namespace dynvo
