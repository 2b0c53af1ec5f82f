#pragma once
// Loop detection over the keyframes in order: candidates by votes in the keyframe databases
// (the keyframes' ORB descriptors, and their lines' LBD descriptors when lines are on),
// kept when consecutive keyframes agree on them (temporal consistency), then verified
// geometrically (loop/loop_verification.h). Plain state, no threads: the loop closer runs it
// on the executor, one keyframe after the other.

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/camera.h"
#include "loop/keyframe_database.h"
#include "loop/loop_keyframe.h"
#include "loop/loop_verification.h"

namespace dynvo {

struct PlaceRecognitionOptions {
  KeyframeDatabaseOptions database;
  // Keyframes of the last 150 frames (5 s at 30 Hz) are never candidates: tracking's local map
  // still holds them, and a revisit of them closes no loop (>= 1).
  int min_frames_apart = 150;
  int min_votes = 20;      // database votes a candidate needs, ORB and LBD together (>= 1)
  int max_candidates = 3;  // best-voted candidates examined per keyframe (>= 1)
  // Consecutive keyframes that must find candidates within 2 keyframes of each other before
  // one is verified; a single lucky keyframe is not enough (>= 1).
  int consistency = 2;
  LoopVerificationOptions verification;
  // Throws InputError naming the key ("loop.<field> ...") when out of range.
  void Check() const;
};

// One candidate examined (a row of loops.csv).
struct LoopCandidate {
  size_t frame = 0;            // the keyframe's input frame
  size_t candidate_frame = 0;  // the earlier keyframe's input frame
  size_t keyframe = 0;         // LoopKeyframe::number of each
  size_t candidate = 0;
  int votes = 0;
  int consistent = 0;     // consecutive keyframes that agreed on it, this one included
  bool verified = false;  // verification ran (consistent enough)
  LoopVerification verification;
  std::string reason;  // why it is not a loop, "" when accepted
  bool accepted() const { return verified && verification.accepted; }
};

class PlaceRecognition {
 public:
  // Throws InputError when the options are out of range.
  PlaceRecognition(const Camera& camera, const PlaceRecognitionOptions& options);

  // Looks for the earlier keyframes this one revisits and verifies the consistent ones, then
  // stores it. Keyframes must come in order (number 0, 1, ...). Returns the candidates examined.
  std::vector<LoopCandidate> Process(std::shared_ptr<const LoopKeyframe> keyframe);

 private:
  // The best-voted earlier keyframes (at least min_frames_apart before) with enough votes.
  std::vector<std::pair<size_t, int>> Candidates(const LoopKeyframe& keyframe) const;

  Camera camera_;
  PlaceRecognitionOptions options_;
  KeyframeDatabase database_;       // the keyframes' ORB descriptors
  KeyframeDatabase line_database_;  // their LBD descriptors (none when lines are off)
  std::vector<std::shared_ptr<const LoopKeyframe>> keyframes_;
  std::vector<std::pair<size_t, int>> last_groups_;  // the previous keyframe's candidates: number, consistent
};

}  // namespace dynvo
