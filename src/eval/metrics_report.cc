#include "eval/metrics_report.h"

#include "core/number_text.h"

namespace dynvo {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string StatisticsLines(const std::string& prefix, const ErrorStatistics& s, const char* unit) {
  std::string out;
  const std::pair<const char*, double> rows[] = {{"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median},
                                                 {"std", s.std},   {"min", s.min},   {"max", s.max}};
  for (const auto& [name, value] : rows) out += prefix + "." + name + " " + FixedText(value, 6) + " " + unit + "\n";
  return out;
}

}  // namespace

std::string FormatRpeText(const RpeResult& result) {
  return "RPE " + result.variant + "\n" + "compared_pose_pairs " + std::to_string(result.pair_count) + " pairs\n" +
         StatisticsLines("translational_error", result.translation_m, "m") +
         StatisticsLines("rotational_error", result.rotation_deg, "deg");
}

std::string FormatAteText(const AteResult& result) {
  return "ATE: " + result.variant + "\n" + "compared_pose_pairs " + std::to_string(result.pairs.size()) + " pairs\n" +
         StatisticsLines("absolute_translational_error", result.translation_m, "m") +
         StatisticsLines("absolute_rotational_error", result.rotation_deg, "deg") +
         (result.alignment_scale != 1.0 ? "alignment_scale " + FixedText(result.alignment_scale, 6) + "\n" : "");
}

nlohmann::json StatisticsJson(const ErrorStatistics& s) {
  return {{"count", s.count}, {"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median},
          {"std", s.std},     {"min", s.min},   {"max", s.max}};
}

nlohmann::json RpeJson(const RpeResult& result, const RpeOptions& options) {
  nlohmann::json j;
  j["metric"] = "rpe";
  j["variant"] = result.variant;
  j["fixed_delta"] = options.fixed_delta;
  j["delta"] = options.delta;
  j["delta_unit"] = DeltaUnitName(options.unit);
  j["offset_s"] = options.offset;
  j["scale"] = options.scale;
  j["closest"] = ClosestLookupName(options.closest);
  j["compared_pose_pairs"] = result.pair_count;
  j["translational_error_m"] = StatisticsJson(result.translation_m);
  j["rotational_error_deg"] = StatisticsJson(result.rotation_deg);
  return j;
}

nlohmann::json AteJson(const AteResult& result, const AteOptions& options) {
  nlohmann::json j;
  j["metric"] = "ate";
  j["variant"] = result.variant;
  j["offset_s"] = options.offset;
  j["scale"] = options.scale;
  j["max_difference_s"] = options.max_difference;
  j["align"] = AteAlignmentName(options.align);
  j["alignment_scale"] = result.alignment_scale;
  j["compared_pose_pairs"] = result.pairs.size();
  j["absolute_translational_error_m"] = StatisticsJson(result.translation_m);
  j["absolute_rotational_error_deg"] = StatisticsJson(result.rotation_deg);
  const Eigen::Matrix3d& r = result.gt_from_est.linear();
  const Eigen::Vector3d& t = result.gt_from_est.translation();
  j["gt_from_est"] = {
      {"rotation", {{r(0, 0), r(0, 1), r(0, 2)}, {r(1, 0), r(1, 1), r(1, 2)}, {r(2, 0), r(2, 1), r(2, 2)}}},
      {"translation", {t.x(), t.y(), t.z()}}};
  return j;
}

std::string RpePairsCsv(const RpeResult& result) {
  std::string out = "stamp_est_0,stamp_est_1,stamp_gt_0,stamp_gt_1,trans_error_m,rot_error_deg\n";
  for (const RpePair& p : result.pairs)
    out += StampText(p.stamp_est_0) + "," + StampText(p.stamp_est_1) + "," + StampText(p.stamp_gt_0) + "," +
           StampText(p.stamp_gt_1) + "," + FixedText(p.trans_error_m, 9) + "," +
           FixedText(p.rot_error_rad * 180.0 / kPi, 9) + "\n";
  return out;
}

std::string AtePairsCsv(const AteResult& result) {
  std::string out = "stamp_gt,stamp_est,trans_error_m,rot_error_deg\n";
  for (const AtePair& p : result.pairs)
    out += StampText(p.stamp_gt) + "," + StampText(p.stamp_est) + "," + FixedText(p.trans_error_m, 9) + "," +
           FixedText(p.rot_error_deg, 9) + "\n";
  return out;
}

}  // namespace dynvo
