#pragma once
// SIGINT and SIGTERM asking a run to stop. The first one sets a flag that the run polls
// before each frame (the frame in hand is finished, the outputs are flushed and run.json
// says "interrupted"); a second one ends the process at once, with status 128 + signal.

namespace dynvo {

class StopSignals {
 public:
  // Installs the handlers; one instance at a time per process.
  StopSignals();
  // Restores the handlers that were there before.
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal that asked to stop (SIGINT or SIGTERM), 0 while none has.
  int received() const;
};

}  // namespace dynvo
