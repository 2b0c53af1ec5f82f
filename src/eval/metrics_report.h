#pragma once
// Text, JSON and CSV renderings of ATE and RPE results. Pure formatting: nothing is printed
// or written here.

#include <string>

#include <nlohmann/json.hpp>

#include "eval/ate.h"
#include "eval/rpe.h"

namespace dynvo {

// The lines evaluate_rpe.py prints (compared_pose_pairs, translational_error.* in m,
// rotational_error.* in deg, 6 decimals), preceded by "RPE <variant>".
std::string FormatRpeText(const RpeResult& result);

// The lines evaluate_ate.py prints (compared_pose_pairs, absolute_translational_error.* in m,
// 6 decimals), preceded by "ATE: <variant>".
std::string FormatAteText(const AteResult& result);

// One JSON object: metric, variant, options, pairs and the statistics.
nlohmann::json RpeJson(const RpeResult& result, const RpeOptions& options);
nlohmann::json AteJson(const AteResult& result, const AteOptions& options);

// CSV with header stamp_est_0,stamp_est_1,stamp_gt_0,stamp_gt_1,trans_error_m,rot_error_deg.
std::string RpePairsCsv(const RpeResult& result);

// CSV with header stamp_gt,stamp_est,trans_error_m.
std::string AtePairsCsv(const AteResult& result);

// {"count", "rmse", "mean", "median", "std", "min", "max"}.
nlohmann::json StatisticsJson(const ErrorStatistics& statistics);

}  // namespace dynvo
