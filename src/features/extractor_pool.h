#pragma once
// Feature extractors for concurrent jobs: each job leases one, so no extractor (with its
// reusable buffers) is ever used by two threads at once; the pool grows to the number of jobs
// that run at the same time and keeps them for reuse.

#include <memory>
#include <mutex>
#include <vector>

#include "core/executor.h"
#include "features/feature_extractor.h"

namespace dynvo {

class ExtractorPool {
 public:
  // Extractors with `options` (which must pass Check()), their levels on `levels_executor`
  // (may be null; must outlive the pool).
  ExtractorPool(const FeatureOptions& options, Executor* levels_executor);

  // One extractor for the lease's lifetime, then back to the pool.
  class Lease {
   public:
    Lease(ExtractorPool& pool, std::unique_ptr<FeatureExtractor> extractor)
        : pool_(pool), extractor_(std::move(extractor)) {}
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    ~Lease() { pool_.Return(std::move(extractor_)); }
    FeatureExtractor& operator*() { return *extractor_; }
    FeatureExtractor* operator->() { return extractor_.get(); }

   private:
    ExtractorPool& pool_;
    std::unique_ptr<FeatureExtractor> extractor_;
  };

  // A free extractor (a new one when all are leased). Thread-safe.
  Lease Acquire();
  const FeatureOptions& options() const { return options_; }

 private:
  void Return(std::unique_ptr<FeatureExtractor> extractor);

  FeatureOptions options_;
  Executor* levels_executor_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<FeatureExtractor>> free_;
};

}  // namespace dynvo
