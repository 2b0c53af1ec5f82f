#include "dataset/trajectory_io.h"

#include <cmath>
#include <fstream>

#include "core/error.h"
#include "core/number_text.h"
#include "dataset/text_lines.h"

namespace dynvo {
namespace {

// Translations beyond this are no camera's: their squares would overflow the metrics' sums.
constexpr double kMaxTranslationM = 1e9;

}  // namespace

Trajectory ParseTrajectory(const std::string& text, const std::string& source) {
  Trajectory trajectory;
  for (const TextLine& line : SplitDataLines(text)) {
    if (line.fields.size() != 8)
      ThrowFileError(source, line.number,
                     "expected 8 columns 'timestamp tx ty tz qx qy qz qw', got " + std::to_string(line.fields.size()));
    double v[8];
    v[0] = ParseStampField(line.fields[0], source, line.number, "timestamp");
    for (int i = 1; i < 8; ++i)
      if (!ParseDouble(line.fields[i], &v[i]))
        ThrowFileError(source, line.number,
                       "column " + std::to_string(i + 1) + " is not a finite number: '" + line.fields[i] + "'");
    for (int i = 1; i < 4; ++i)
      if (std::abs(v[i]) > kMaxTranslationM)
        ThrowFileError(source, line.number,
                       "column " + std::to_string(i + 1) + " is " + line.fields[i] +
                           ": a translation beyond 1e9 m is no camera's (a diverged estimate?)");
    const double qnorm = std::sqrt(v[4] * v[4] + v[5] * v[5] + v[6] * v[6] + v[7] * v[7]);
    if (qnorm < 1e-9) ThrowFileError(source, line.number, "quaternion has zero length");
    if (!std::isfinite(qnorm)) ThrowFileError(source, line.number, "quaternion too large to normalise");
    if (!trajectory.empty() && v[0] < trajectory.back().stamp)
      ThrowFileError(source, line.number, "timestamps must increase, got " + line.fields[0] + " after a larger one");
    const StampedPose pose{v[0], PoseFromTum({v[1], v[2], v[3]}, v[4], v[5], v[6], v[7])};
    // A repeated stamp (real TUM files have them: fr2_desk repeats 1311868229.5760) keeps
    // its last line, as the TUM scripts' dict does.
    if (!trajectory.empty() && v[0] == trajectory.back().stamp)
      trajectory.back() = pose;
    else
      trajectory.push_back(pose);
  }
  return trajectory;
}

Trajectory ReadTrajectory(const std::string& path) { return ParseTrajectory(ReadTextFile(path), path); }

std::string FormatTrajectory(const Trajectory& trajectory) {
  std::string out;
  for (const StampedPose& p : trajectory) {
    const Eigen::Vector3d& t = p.world_from_camera.translation();
    const Eigen::Quaterniond q = PoseQuaternion(p.world_from_camera);
    out += StampText(p.stamp);
    for (double v : {t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()}) out += " " + FixedText(v, 7);
    out += "\n";
  }
  return out;
}

void WriteTrajectory(const std::string& path, const Trajectory& trajectory) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) ThrowFileError(path, 0, "cannot write file");
  out << FormatTrajectory(trajectory);
  if (!out) ThrowFileError(path, 0, "write failed");
}

}  // namespace dynvo
