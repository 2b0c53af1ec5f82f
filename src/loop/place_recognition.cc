#include "loop/place_recognition.h"

#include <algorithm>
#include <cstdlib>

#include "core/error.h"

namespace dynvo {

void PlaceRecognitionOptions::Check() const {
  database.Check();
  RequireOption(min_frames_apart >= 1, "loop", "min_frames_apart", ">= 1", min_frames_apart);
  RequireOption(min_votes >= 1, "loop", "min_votes", ">= 1", min_votes);
  RequireOption(max_candidates >= 1, "loop", "max_candidates", ">= 1", max_candidates);
  RequireOption(consistency >= 1, "loop", "consistency", ">= 1", consistency);
  verification.Check();
}

namespace {

constexpr size_t kGroupReach = 2;  // keyframes apart that still count as the same place

}  // namespace

PlaceRecognition::PlaceRecognition(const Camera& camera, const PlaceRecognitionOptions& options)
    : camera_(camera), options_(options), database_(options.database), line_database_(options.database) {
  options_.Check();
}

std::vector<std::pair<size_t, int>> PlaceRecognition::Candidates(const LoopKeyframe& keyframe) const {
  size_t before = 0;  // keyframes come in frame order: those far enough back are a prefix
  while (before < keyframes_.size() &&
         keyframes_[before]->frame + static_cast<size_t>(options_.min_frames_apart) <= keyframe.frame)
    ++before;
  std::vector<int> votes = database_.Votes(keyframe.descriptors, before);
  const std::vector<int> line_votes = line_database_.Votes(keyframe.line_descriptors, before);
  for (size_t k = 0; k < votes.size(); ++k) votes[k] += line_votes[k];
  std::vector<std::pair<size_t, int>> ranked;
  for (size_t k = 0; k < votes.size(); ++k)
    if (votes[k] >= options_.min_votes) ranked.emplace_back(k, votes[k]);
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  if (ranked.size() > static_cast<size_t>(options_.max_candidates)) ranked.resize(options_.max_candidates);
  return ranked;
}

std::vector<LoopCandidate> PlaceRecognition::Process(std::shared_ptr<const LoopKeyframe> keyframe) {
  if (keyframe->number != keyframes_.size())
    throw InputError("PlaceRecognition::Process: keyframe " + std::to_string(keyframe->number) +
                     " out of order, expected " + std::to_string(keyframes_.size()));
  std::vector<LoopCandidate> examined;
  std::vector<std::pair<size_t, int>> groups;
  for (const auto& [number, votes] : Candidates(*keyframe)) {
    LoopCandidate c;
    c.frame = keyframe->frame;
    c.keyframe = keyframe->number;
    c.candidate = number;
    c.candidate_frame = keyframes_[number]->frame;
    c.votes = votes;
    c.consistent = 1;
    for (const auto& [earlier, consistent] : last_groups_)
      if (std::max(number, earlier) - std::min(number, earlier) <= kGroupReach)
        c.consistent = std::max(c.consistent, consistent + 1);
    groups.emplace_back(number, c.consistent);
    c.verified = c.consistent >= options_.consistency;
    if (c.verified) {
      c.verification = VerifyLoop(*keyframe, *keyframes_[number], camera_, options_.verification);
      c.reason = c.verification.reason;
    } else {
      c.reason = "not yet consistent";
    }
    examined.push_back(c);
  }
  last_groups_ = groups;
  database_.Add(keyframe->descriptors);
  line_database_.Add(keyframe->line_descriptors);
  keyframes_.push_back(std::move(keyframe));
  return examined;
}

}  // namespace dynvo
