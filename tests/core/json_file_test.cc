#include "core/json_file.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

std::string ErrorOf(const std::string& text) {
  try {
    ParseJsonStrictly(text, "config.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ParseJsonStrictly, ReadsCommentsAndNamesARepeatedKeyWithItsPath) {
  const nlohmann::json j = ParseJsonStrictly(R"({"a": 1, // the first
    "b": {"c": [1, {"d": 2}], "e": 3}})",
                                             "config.json");
  EXPECT_EQ(j["b"]["c"][1]["d"], 2);
  EXPECT_EQ(ErrorOf(R"({"features": {"num_features": 900, "num_features": 1200}})"),
            "config.json: key 'features.num_features' appears twice");
  EXPECT_EQ(ErrorOf(R"({"a": 1, "a": 1})"), "config.json: key 'a' appears twice");
  // The same key in two objects is no repetition, nor in two objects of one array.
  EXPECT_EQ(ErrorOf(R"({"x": {"k": 1}, "y": {"k": 2}, "z": [{"k": 1}, {"k": 2}]})"), "");
  EXPECT_EQ(ErrorOf("{").rfind("config.json: not valid JSON: ", 0), 0u);
  EXPECT_EQ(ErrorOf(R"({"a": 1e309})").rfind("config.json: not valid JSON: ", 0), 0u);  // found by the fuzz test
}

}  // namespace
}  // namespace dynvo
