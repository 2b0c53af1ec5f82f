#pragma once
// timing.csv: one row per frame, written as frames finish so a failed run keeps its rows.

#include <fstream>
#include <string>

#include "odometry/frame_record.h"

namespace dynvo {

class TimingCsvWriter {
 public:
  // Creates (truncates) the file and writes the header. Throws InputError when it cannot.
  explicit TimingCsvWriter(const std::string& path);
  // Appends the row of one frame and flushes it.
  void Write(const FrameRecord& record);

  // The column names, in order.
  static const char* Header();

 private:
  std::string path_;
  std::ofstream out_;
};

}  // namespace dynvo
