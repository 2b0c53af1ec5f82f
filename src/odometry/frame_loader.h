#pragma once
// Decodes a sequence's frames in order, optionally ahead of use in a second thread (bounded
// queue), so that PNG decoding overlaps processing. Load errors reach the consumer in order.

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "dataset/tum_dataset.h"

namespace dynvo {

struct LoadedFrame {
  RgbdFrame frame;
  cv::Mat truth_mask;    // ground-truth dynamic mask when the sequence has masks
  double load_ms = 0.0;  // decoding time of the PNGs (and mask)
};

class FrameLoader {
 public:
  // Loads frames [0, count) of `dataset`, which must outlive the loader. `with_masks` also
  // loads ground-truth masks. With `preload`, a thread keeps up to `queue_size` frames ready.
  FrameLoader(const TumDataset& dataset, size_t count, bool with_masks, bool preload,
              size_t queue_size = 4);
  ~FrameLoader();
  FrameLoader(const FrameLoader&) = delete;
  FrameLoader& operator=(const FrameLoader&) = delete;

  // The next frame in order; nullopt after the last. Rethrows the error (InputError) of a
  // frame that failed to load, at that frame's turn.
  std::optional<LoadedFrame> Next();

 private:
  LoadedFrame LoadOne(size_t index) const;
  void Run();

  const TumDataset& dataset_;
  const size_t count_;
  const bool with_masks_;
  const bool preload_;
  const size_t queue_size_;
  size_t next_index_ = 0;  // synchronous mode only

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<LoadedFrame> queue_;
  std::exception_ptr error_;
  bool producer_done_ = false;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace dynvo
