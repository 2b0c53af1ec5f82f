#pragma once
// Decodes a sequence's frames in order, a few ahead of use on the executor, so that PNG
// decoding overlaps processing. Load errors reach the consumer in order.

#include <deque>
#include <optional>

#include "core/executor.h"
#include "dataset/tum_dataset.h"

namespace dynvo {

struct LoadedFrame {
  RgbdFrame frame;
  cv::Mat truth_mask;    // ground-truth dynamic mask when the sequence has masks
  cv::Mat still_people;  // of it, the pixels of people not moving (kStillPersonLabel), 255
  double load_ms = 0.0;  // decoding time of the PNGs (and mask)
};

class FrameLoader {
 public:
  // Loads frames [0, count) of `dataset`, which must outlive the loader, as must `executor`.
  // `with_masks` also loads ground-truth masks. Up to `queue_size` frames are decoded ahead.
  FrameLoader(const TumDataset& dataset, size_t count, bool with_masks, Executor& executor, size_t queue_size = 4);

  // The next frame in order; nullopt after the last. Rethrows the error (InputError) of a
  // frame that failed to load, at that frame's turn.
  std::optional<LoadedFrame> Next();

 private:
  LoadedFrame LoadOne(size_t index) const;

  const TumDataset& dataset_;
  const size_t count_;
  const bool with_masks_;
  Executor& executor_;
  const size_t queue_size_;
  size_t next_to_start_ = 0;
  std::deque<Task<LoadedFrame>> ahead_;  // frames being decoded, in order
};

}  // namespace dynvo
