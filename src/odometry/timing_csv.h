#pragma once
// timing.csv: one row per frame, written as frames finish so a failed run keeps its rows.

#include <string>

#include "core/output_file.h"
#include "odometry/frame_record.h"

namespace dynvo {

class TimingCsvWriter {
 public:
  // Creates (truncates) the file and writes the header. Throws InputError when it cannot.
  explicit TimingCsvWriter(const std::string& path);
  // Appends the row of one frame and flushes it. Throws InputError naming the file when the
  // write fails.
  void Write(const FrameRecord& record);

  // The column names, in order.
  static const char* Header();

 private:
  AppendedFile file_;
};

}  // namespace dynvo
