#include "pipeline/feature_stage.h"

#include <chrono>
#include <utility>

#include "core/same_image.h"
#include "core/stopwatch.h"
#include "dynamic_mask/background_fill.h"
#include "dynamic_mask/mask_morphology.h"
#include "features/feature_filter.h"
#include "pipeline/mask_source.h"

namespace dynvo {
FeatureStage::FeatureStage(const Camera& camera, const FeatureOptions& options, const ImageArea& image_area,
                           Executor& executor)
    : camera_(camera),
      options_(options),
      image_area_(image_area),
      executor_(executor),
      extractors_(options, &executor) {}

void FeatureStage::Start(const RgbdFrame& frame) {
  pending_.Reset();  // one for another frame is dropped, with its error
  pending_lines_.Reset();
  pending_gray_ = frame.gray;
  if (options_.lines.enabled)
    pending_lines_ = executor_.Submit([this, frame] {
      const auto start = SteadyClock::now();
      LineDetection detection{DetectLines(frame.gray, frame.depth, camera_, options_.lines), 0.0};
      detection.ms = MillisecondsSince(start);
      return detection;
    });
  pending_ = executor_.Submit([this, frame] {
    Extraction extraction;
    const auto start = SteadyClock::now();
    ExtractorPool::Lease extractor = extractors_.Acquire();
    extraction.features = extractor->Extract(frame.gray, frame.depth, camera_, cv::Mat(),
                                             options_.refill_reuse_corners ? &extraction.corners : nullptr);
    extraction.ms = MillisecondsSince(start);
    return extraction;
  });
}

void FeatureStage::Begin(const RgbdFrame& frame) {
  if (!pending_.valid() || !SameImage(pending_gray_, frame.gray)) Start(frame);
}

void FeatureStage::LookAhead(const RgbdFrame& next) { Start(next); }

FrameFeatures FeatureStage::Refill(const RgbdFrame& frame, const cv::Mat& mask, const cv::Mat& described,
                                   const DetectedCorners& corners) {
  cv::Mat exclude = mask.clone();  // the mask grown by the margin on every side
  DilateMask(MorphShape::kRect, 2 * options_.refill_margin_px + 1, 1, &exclude);
  ExtractorPool::Lease extractor = extractors_.Acquire();
  return corners.empty() ? extractor->Extract(described, frame.depth, camera_, exclude)
                         : extractor->ExtractFromCorners(corners, described, frame.depth, camera_, exclude);
}

FeaturePacket FeatureStage::Finish(const RgbdFrame& frame, const MaskPacket& mask) {
  Begin(frame);
  Extraction extraction = pending_.Get();
  pending_gray_.release();
  FeaturePacket packet;
  packet.frame = frame.index;
  packet.features_ms = extraction.ms;
  auto start = SteadyClock::now();
  if (!mask.mask.empty())
    packet.split = SplitByMask(extraction.features, mask.mask);
  else
    packet.split.kept = std::move(extraction.features);
  packet.filter_ms = MillisecondsSince(start);
  if (pending_lines_.valid()) {
    start = SteadyClock::now();
    const LineDetection detection = pending_lines_.Get();
    packet.lines = KeepLines(detection.lines, mask.mask, options_.lines, &packet.masked_lines);
    packet.lines_ms = detection.ms + MillisecondsSince(start);
  }
  // The frame as the refill describes it: with refill_from_background, the mask's pixels are the
  // static background of earlier frames, kept for the next frame (also when nothing is refilled,
  // so that what moves stays out of it).
  cv::Mat described = frame.gray;
  if (options_.refill_from_background) {
    start = SteadyClock::now();
    if (!mask.mask.empty() && mask.has_motion)
      described = FillMaskFromBackground(frame.gray, mask.mask, background_gray_, mask.current_from_previous,
                                         kBackgroundFillMarginPx, image_area_);
    background_gray_ = described;
    packet.described = described;
    packet.features_ms += MillisecondsSince(start);
  }
  if (options_.refill_outside_mask && packet.split.removed.size() > 0) {
    start = SteadyClock::now();
    packet.split.kept = Refill(frame, mask.mask, described, extraction.corners);
    packet.split.kept_indices.clear();  // the kept features no longer index the first extraction
    packet.features_ms += MillisecondsSince(start);
  }
  return packet;
}

}  // namespace dynvo
