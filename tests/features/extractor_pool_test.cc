// The extractor pool: leases held at once get distinct extractors; a returned one is reused.

#include "features/extractor_pool.h"

#include <gtest/gtest.h>

namespace dynvo {
namespace {

TEST(ExtractorPool, LeasesHeldAtOnceGetDistinctExtractorsAndReturnedOnesAreReused) {
  ExtractorPool pool(FeatureOptions{}, nullptr);
  const FeatureExtractor* first = nullptr;
  {
    ExtractorPool::Lease a = pool.Acquire();
    ExtractorPool::Lease b = pool.Acquire();
    EXPECT_NE(&*a, &*b);
    first = &*a;
  }
  ExtractorPool::Lease again = pool.Acquire();
  ExtractorPool::Lease other = pool.Acquire();
  EXPECT_TRUE(&*again == first || &*other == first);  // no third extractor was made
}

TEST(ExtractorPool, BadOptionsAreRefusedAtOnce) {
  FeatureOptions options;
  options.num_levels = 0;
  EXPECT_ANY_THROW(ExtractorPool(options, nullptr));
}

}  // namespace
}  // namespace dynvo
