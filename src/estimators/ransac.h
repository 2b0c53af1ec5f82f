#pragma once
// One RANSAC loop for every robust estimator (COLMAP's pattern, optim/ransac.h). An estimator
// supplies its minimal sample size, a model from a minimal sample, the squared residual of every
// datum for a model, and a model refitted on all inliers of a new best hypothesis (local
// optimisation, which lets the stopping rule see the true inlier ratio). Hypotheses are scored by
// MSAC: squared residuals truncated at the threshold, so that among models with as many inliers
// the tighter one wins. The loop stops once an all-inlier sample has been drawn with the given
// confidence. Samples come from a seeded std::mt19937: same data and seed, same result.
//
// An estimator:
//   using Model = ...;
//   static constexpr int kMinSamples = ...;
//   bool Estimate(const std::vector<int>& sample, Model* model) const;   // false: degenerate sample
//   void Residuals(const Model& model, std::vector<double>* squared) const;  // one per datum
//   bool Refit(const std::vector<int>& inliers, Model* model) const;     // false: keep the model

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace dynvo {

struct RansacOptions {
  double max_error = 1.0;     // inlier threshold on the residual, in the estimator's unit (> 0)
  double confidence = 0.99;   // stop once an all-inlier sample was drawn this surely, (0, 1]
  int max_iterations = 500;   // hypotheses at most (>= 1)
  int min_refit_inliers = 0;  // a new best hypothesis is refitted when it has at least this many
  unsigned seed = 1;          // of the sampler

  // Throws InputError naming `prefix` + "." + field when a value is out of range.
  void Check(const std::string& prefix) const;
};

template <typename Model>
struct RansacResult {
  bool found = false;            // some sample gave a model
  Model model{};                 // the best (valid when found)
  std::vector<uint8_t> inliers;  // per datum, 1 = residual below max_error for `model`
  int num_inliers = 0;
  int iterations = 0;  // hypotheses drawn
};

// Hypotheses needed for an all-inlier sample of `sample_size` with `confidence` at
// `inlier_ratio`, at most `cap`.
int RansacIterationsNeeded(double inlier_ratio, int sample_size, double confidence, int cap);

namespace internal {

struct MsacScore {
  double score = std::numeric_limits<double>::infinity();
  int inliers = 0;
};

inline MsacScore ScoreResiduals(const std::vector<double>& squared, double threshold_sq) {
  MsacScore s{0.0, 0};
  for (double e : squared) {
    if (e < threshold_sq) {
      s.score += e;
      ++s.inliers;
    } else {
      s.score += threshold_sq;
    }
  }
  return s;
}

// `count` distinct indices in [0, n) (n >= count), by rejection.
inline void DrawSample(std::mt19937& rng, int n, int count, std::vector<int>* sample) {
  std::uniform_int_distribution<int> pick(0, n - 1);
  sample->resize(static_cast<size_t>(count));
  for (int k = 0; k < count; ++k) {
    int candidate;
    do {
      candidate = pick(rng);
    } while (std::find(sample->begin(), sample->begin() + k, candidate) != sample->begin() + k);
    (*sample)[static_cast<size_t>(k)] = candidate;
  }
}

}  // namespace internal

// The best model of `num_data` data under `estimator` (options must pass Check()). Fewer data
// than the minimal sample, or only degenerate samples, give found = false.
template <typename Estimator>
RansacResult<typename Estimator::Model> RunRansac(const Estimator& estimator, int num_data,
                                                  const RansacOptions& options) {
  using Model = typename Estimator::Model;
  constexpr int kMin = Estimator::kMinSamples;
  RansacResult<Model> result;
  result.inliers.assign(static_cast<size_t>(std::max(num_data, 0)), 0);
  if (num_data < kMin) return result;
  const double threshold_sq = options.max_error * options.max_error;
  std::mt19937 rng(options.seed);
  std::vector<int> sample, inlier_list;
  std::vector<double> squared;
  internal::MsacScore best;
  int needed = options.max_iterations;
  for (; result.iterations < needed; ++result.iterations) {
    internal::DrawSample(rng, num_data, kMin, &sample);
    Model model;
    if (!estimator.Estimate(sample, &model)) continue;
    result.found = true;
    estimator.Residuals(model, &squared);
    internal::MsacScore score = internal::ScoreResiduals(squared, threshold_sq);
    if (score.score >= best.score) continue;
    if (score.inliers >= std::max(options.min_refit_inliers, kMin)) {
      inlier_list.clear();
      for (int i = 0; i < num_data; ++i)
        if (squared[static_cast<size_t>(i)] < threshold_sq) inlier_list.push_back(i);
      Model refit = model;
      if (estimator.Refit(inlier_list, &refit)) {
        estimator.Residuals(refit, &squared);
        const internal::MsacScore refit_score = internal::ScoreResiduals(squared, threshold_sq);
        if (refit_score.score < score.score) {
          model = refit;
          score = refit_score;
        }
      }
    }
    best = score;
    result.model = model;
    needed = std::max(result.iterations + 1, RansacIterationsNeeded(static_cast<double>(score.inliers) / num_data, kMin,
                                                                    options.confidence, options.max_iterations));
  }
  if (!result.found) return result;
  estimator.Residuals(result.model, &squared);
  for (int i = 0; i < num_data; ++i)
    result.inliers[static_cast<size_t>(i)] = squared[static_cast<size_t>(i)] < threshold_sq;
  result.num_inliers = static_cast<int>(std::count(result.inliers.begin(), result.inliers.end(), 1));
  return result;
}

}  // namespace dynvo
