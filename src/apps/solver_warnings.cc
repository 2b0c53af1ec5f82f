#include "apps/solver_warnings.h"

#include <glog/logging.h>

namespace dynvo {

void ShowOnlySolverErrors() { FLAGS_minloglevel = google::GLOG_ERROR; }

}  // namespace dynvo
