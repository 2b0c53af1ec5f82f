#pragma once
// The small generated sequence the executables' tests run on: 320x240, fx 270, in DIR/seq.

#include <string>

#include "support/temp_dir.h"
#include "synth/synthetic_sequence.h"
#include "synth/tum_writer.h"

namespace dynvo::test {

// Writes a `frames`-frame generated sequence into dir/seq and returns its path: enough to run,
// not to measure accuracy.
inline std::string MakeSmallSequence(const TempDir& dir, int frames) {
  SyntheticSequenceOptions options;
  options.frames = frames;
  options.camera.width = 320;
  options.camera.height = 240;
  options.camera.fx = options.camera.fy = 270;
  options.camera.cx = 160;
  options.camera.cy = 120;
  const std::string folder = (dir.path() / "seq").string();
  PrepareOutputFolder(folder, /*force=*/false);
  WriteSyntheticSequence(options, folder);
  return folder;
}

}  // namespace dynvo::test
