#pragma once
// A generated sequence written for an end-to-end test.

#include <filesystem>
#include <string>

#include "synth/synthetic_sequence.h"
#include "synth/tum_writer.h"

namespace dynvo {
namespace test {

// Writes the sequence `options` describes into the new folder `folder` (TUM layout) and
// returns the folder's path.
inline std::string WriteGeneratedSequence(const SyntheticSequenceOptions& options,
                                          const std::filesystem::path& folder) {
  const std::string path = folder.string();
  PrepareOutputFolder(path, /*force=*/false);
  WriteSyntheticSequence(options, path);
  return path;
}

}  // namespace test
}  // namespace dynvo
