#include "apps/solver_warnings.h"

#include <string>

#include <glog/logging.h>
#include <gtest/gtest.h>

namespace dynvo {
namespace {

// What Ceres logs reaches stderr from glog: after the call its warnings stay off, its errors
// still show.
TEST(SolverWarnings, WarningsStayOffTheTerminalAndErrorsShow) {
  const int before = FLAGS_minloglevel;
  testing::internal::CaptureStderr();
  LOG(WARNING) << "dynvo test: a warning before";
  ShowOnlySolverErrors();
  LOG(INFO) << "dynvo test: info after";
  LOG(WARNING) << "dynvo test: a warning after";
  LOG(ERROR) << "dynvo test: an error after";
  const std::string printed = testing::internal::GetCapturedStderr();
  FLAGS_minloglevel = before;
  EXPECT_NE(printed.find("a warning before"), std::string::npos) << printed;
  EXPECT_EQ(printed.find("info after"), std::string::npos) << printed;
  EXPECT_EQ(printed.find("a warning after"), std::string::npos) << printed;
  EXPECT_NE(printed.find("an error after"), std::string::npos) << printed;
}

}  // namespace
}  // namespace dynvo
