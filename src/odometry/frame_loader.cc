#include "odometry/frame_loader.h"

#include <chrono>

namespace dynvo {

FrameLoader::FrameLoader(const TumDataset& dataset, size_t count, bool with_masks, bool preload,
                         size_t queue_size)
    : dataset_(dataset),
      count_(count),
      with_masks_(with_masks),
      preload_(preload),
      queue_size_(queue_size < 1 ? 1 : queue_size) {
  if (preload_) thread_ = std::thread([this] { Run(); });
}

FrameLoader::~FrameLoader() {
  if (thread_.joinable()) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    changed_.notify_all();
    thread_.join();
  }
}

LoadedFrame FrameLoader::LoadOne(size_t index) const {
  const auto start = std::chrono::steady_clock::now();
  LoadedFrame loaded;
  loaded.frame = dataset_.Load(index);
  if (with_masks_) loaded.truth_mask = dataset_.LoadMask(index);
  loaded.load_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return loaded;
}

void FrameLoader::Run() {
  for (size_t i = 0; i < count_; ++i) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [this] { return stop_ || queue_.size() < queue_size_; });
      if (stop_) return;
    }
    try {
      LoadedFrame loaded = LoadOne(i);
      std::lock_guard<std::mutex> lock(mutex_);
      queue_.push_back(std::move(loaded));
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      error_ = std::current_exception();
      producer_done_ = true;
      changed_.notify_all();
      return;
    }
    changed_.notify_all();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  producer_done_ = true;
  changed_.notify_all();
}

std::optional<LoadedFrame> FrameLoader::Next() {
  if (!preload_) {
    if (next_index_ >= count_) return std::nullopt;
    return LoadOne(next_index_++);
  }
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return !queue_.empty() || producer_done_; });
  if (!queue_.empty()) {
    LoadedFrame loaded = std::move(queue_.front());
    queue_.pop_front();
    lock.unlock();
    changed_.notify_all();
    return loaded;
  }
  if (error_) std::rethrow_exception(error_);
  return std::nullopt;
}

}  // namespace dynvo
