#include "odometry/timing_csv.h"

#include <sstream>
#include <string>

#include "core/csv_text.h"
#include "core/error.h"
#include "core/number_text.h"

namespace dynvo {
namespace {

std::string Fixed(double v, int decimals) { return FixedText(v, decimals); }

}  // namespace

const char* TimingCsvWriter::Header() {
  return "frame,stamp,load_ms,dynamic_mask_ms,features_ms,filter_ms,match_ms,pose_ms,map_ms,"
         "local_ba_ms,processing_ms,features_total,features_kept,features_removed,features_readmitted,"
         "dynamic_ratio,mask_threshold,mask_ok,mask_note,tracking_state,tracking_note,matches,inliers,"
         "new_points_rejected,coherent_motion_rejected,keyframe,"
         "mask_precision,mask_recall,mask_iou,people,detection_age,people_moving,people_still,detector_ms,"
         "detector_status,local_ba_converged,lines,lines_matched,line_inliers,lines_added,lines_ms";
}

TimingCsvWriter::TimingCsvWriter(const std::string& path) : file_(path) { file_.Append(std::string(Header()) + "\n"); }

void TimingCsvWriter::Write(const FrameRecord& r) {
  const StageTimes& t = r.times;
  std::ostringstream row;
  row << r.index << ',' << StampText(r.stamp) << ',' << Fixed(t.load_ms, 3) << ',' << Fixed(t.dynamic_mask_ms, 3) << ','
      << Fixed(t.features_ms, 3) << ',' << Fixed(t.filter_ms, 3) << ',' << Fixed(t.match_ms, 3) << ','
      << Fixed(t.pose_ms, 3) << ',' << Fixed(t.map_ms, 3) << ',' << Fixed(t.local_ba_ms, 3) << ','
      << Fixed(t.processing_ms, 3) << ',' << r.features_total << ',' << r.features_kept << ',' << r.features_removed
      << ',' << r.features_readmitted << ',' << Fixed(r.dynamic_ratio, 5) << ','
      << (r.mask_threshold >= 0 ? std::to_string(r.mask_threshold) : std::string()) << ',' << (r.mask_ok ? 1 : 0) << ','
      << CsvText(r.mask_note) << ',' << ToString(r.state) << ',' << CsvText(r.tracking_note) << ',' << r.num_matches
      << ',' << r.num_inliers << ',' << r.new_points_rejected << ',' << r.coherent_motion_rejected << ','
      << (r.keyframe ? 1 : 0) << ',';
  if (r.mask_quality) {
    row << Fixed(r.mask_quality->Precision(), 5) << ',' << Fixed(r.mask_quality->Recall(), 5) << ','
        << Fixed(r.mask_quality->Iou(), 5);
  } else {
    row << ",,";
  }
  const bool judged = r.people >= 0 && r.people_moving >= 0;
  row << ',' << (r.people >= 0 ? std::to_string(r.people) : std::string()) << ','
      << (r.detection_age >= 0 ? std::to_string(r.detection_age) : std::string()) << ','
      << (judged ? std::to_string(r.people_moving) : std::string()) << ','
      << (judged ? std::to_string(r.people - r.people_moving) : std::string()) << ','
      << (r.people >= 0 ? Fixed(t.detector_ms, 3) : std::string()) << ',' << r.detection << ','
      << (r.local_ba_converged >= 0 ? std::to_string(r.local_ba_converged) : std::string());
  if (r.lines >= 0) {
    row << ',' << r.lines << ',' << r.lines_matched << ',' << r.line_inliers << ',' << r.lines_added << ','
        << Fixed(t.lines_ms, 3) << '\n';
  } else {
    row << ",,,,,\n";
  }
  file_.Append(row.str());
}

}  // namespace dynvo
