#include "odometry/frame_loader.h"
#include "core/stopwatch.h"

#include <chrono>

namespace dynvo {

FrameLoader::FrameLoader(const TumDataset& dataset, size_t count, bool with_masks, Executor& executor,
                         size_t queue_size)
    : dataset_(dataset),
      count_(count),
      with_masks_(with_masks),
      executor_(executor),
      queue_size_(queue_size < 1 ? 1 : queue_size) {}

LoadedFrame FrameLoader::LoadOne(size_t index) const {
  const auto start = SteadyClock::now();
  LoadedFrame loaded;
  loaded.frame = dataset_.Load(index);
  if (with_masks_) {
    const cv::Mat labels = dataset_.LoadMaskLabels(index);
    loaded.truth_mask = labels > 0;
    loaded.still_people = labels == kStillPersonLabel;
  }
  loaded.load_ms = MillisecondsSince(start);
  return loaded;
}

std::optional<LoadedFrame> FrameLoader::Next() {
  while (ahead_.size() < queue_size_ && next_to_start_ < count_) {
    const size_t index = next_to_start_++;
    ahead_.push_back(executor_.Submit([this, index] { return LoadOne(index); }));
  }
  if (ahead_.empty()) return std::nullopt;
  Task<LoadedFrame> task = std::move(ahead_.front());
  ahead_.pop_front();
  return task.Get();
}

}  // namespace dynvo
