#include "features/extractor_pool.h"

#include <utility>

namespace dynvo {

ExtractorPool::ExtractorPool(const FeatureOptions& options, Executor* levels_executor)
    : options_(options), levels_executor_(levels_executor) {
  free_.push_back(std::make_unique<FeatureExtractor>(options_, levels_executor_));  // checks the options
}

ExtractorPool::Lease ExtractorPool::Acquire() {
  std::unique_ptr<FeatureExtractor> extractor;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!free_.empty()) {
      extractor = std::move(free_.back());
      free_.pop_back();
    }
  }
  if (!extractor) extractor = std::make_unique<FeatureExtractor>(options_, levels_executor_);
  return Lease(*this, std::move(extractor));
}

void ExtractorPool::Return(std::unique_ptr<FeatureExtractor> extractor) {
  std::lock_guard<std::mutex> lock(mutex_);
  free_.push_back(std::move(extractor));
}

}  // namespace dynvo
