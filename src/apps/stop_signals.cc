#include "apps/stop_signals.h"

#include <unistd.h>

#include <csignal>

namespace dynvo {
namespace {

// A signal handler can reach nothing but static storage: the one piece of process-wide
// state in the project, owned by the single StopSignals instance.
volatile std::sig_atomic_t stop_signal = 0;
struct sigaction previous_int, previous_term;

void OnStopSignal(int signal) {
  if (stop_signal != 0) _exit(128 + signal);  // asked twice: stop now
  stop_signal = signal;
  static const char kNote[] = "\ndynvo: stopping after the current frame (signal again to quit at once)\n";
  const ssize_t written = write(STDERR_FILENO, kNote, sizeof(kNote) - 1);
  (void)written;  // nothing to do when stderr is gone
}

}  // namespace

StopSignals::StopSignals() {
  stop_signal = 0;
  struct sigaction action {};
  action.sa_handler = OnStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

int StopSignals::received() const { return stop_signal; }

}  // namespace dynvo
