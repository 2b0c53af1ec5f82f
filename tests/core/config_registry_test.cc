#include "core/config_registry.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "support/input_error.h"

namespace dynvo {
namespace {

struct Fields {
  int count = 3;
  double ratio = 0.5;
  bool on = true;
  unsigned seed = 1;
  std::string mode = "a";
};

ConfigRegistry Registry(Fields* f) {
  ConfigRegistry r;
  r.Bind("stage.count", &f->count, "a count");
  r.Bind("stage.ratio", &f->ratio, "a ratio");
  r.Bind("stage.on", &f->on, "a switch");
  r.Bind("other.seed", &f->seed, "a seed");
  r.BindChoice(
      "other.mode", {"a", "b"}, [f] { return f->mode; }, [f](const std::string& s) { f->mode = s; }, "a choice");
  return r;
}

TEST(ConfigRegistry, AppliesNestedKeysAndSkipsComments) {
  Fields f;
  ConfigRegistry r = Registry(&f);
  r.Apply(nlohmann::json::parse(R"({"_comment": "x", "stage": {"count": 7, "ratio": 2, "on": false},
                                     "other": {"seed": 9, "mode": "b"}})"),
          "c.json");
  EXPECT_EQ(f.count, 7);
  EXPECT_DOUBLE_EQ(f.ratio, 2.0);
  EXPECT_FALSE(f.on);
  EXPECT_EQ(f.seed, 9u);
  EXPECT_EQ(f.mode, "b");
}

TEST(ConfigRegistry, UnknownKeyNamesKeyAndSource) {
  Fields f;
  ConfigRegistry r = Registry(&f);
  const std::string msg = test::InputErrorOf([&] { r.Apply(nlohmann::json::parse(R"({"stage": {"cout": 1}})"), "c.json"); });
  EXPECT_NE(msg.find("c.json"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknown key 'stage.cout'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("stage.count"), std::string::npos) << "suggests the section's keys: " << msg;
}

TEST(ConfigRegistry, WrongTypesAreRejectedWithKey) {
  Fields f;
  ConfigRegistry r = Registry(&f);
  EXPECT_NE(test::InputErrorOf([&] {
              r.Apply(nlohmann::json::parse(R"({"stage": {"count": 1.5}})"), "c.json");
            }).find("key 'stage.count' expects an integer, got 1.5"),
            std::string::npos);
  EXPECT_NE(test::InputErrorOf([&] {
              r.Apply(nlohmann::json::parse(R"({"stage": {"on": 1}})"), "c.json");
            }).find("key 'stage.on' expects true or false"),
            std::string::npos);
  EXPECT_NE(
      test::InputErrorOf([&] { r.Apply(nlohmann::json::parse(R"({"other": {"seed": -1}})"), "c.json"); }).find("'other.seed'"),
      std::string::npos);
  EXPECT_NE(test::InputErrorOf([&] {
              r.Apply(nlohmann::json::parse(R"({"other": {"mode": "c"}})"), "c.json");
            }).find("one of \"a\", \"b\""),
            std::string::npos);
  EXPECT_NE(test::InputErrorOf([&] { r.Apply(nlohmann::json::parse("[1]"), "c.json"); }).find("JSON object"), std::string::npos);
  EXPECT_EQ(f.count, 3) << "a rejected value leaves the field alone";
}

TEST(ConfigRegistry, OverridesParseJsonOrText) {
  Fields f;
  ConfigRegistry r = Registry(&f);
  r.ApplyOverride("stage.count=12");
  r.ApplyOverride("stage.on=false");
  r.ApplyOverride("other.mode=b");      // plain text
  r.ApplyOverride("stage.ratio=1e-3");  // JSON number
  EXPECT_EQ(f.count, 12);
  EXPECT_FALSE(f.on);
  EXPECT_EQ(f.mode, "b");
  EXPECT_DOUBLE_EQ(f.ratio, 1e-3);
  EXPECT_NE(test::InputErrorOf([&] { r.ApplyOverride("stage.count"); }).find("expected key=value"), std::string::npos);
  EXPECT_NE(test::InputErrorOf([&] { r.ApplyOverride("nope=1"); }).find("--set: unknown key 'nope'"), std::string::npos);
}

TEST(ConfigRegistry, IntegerListsTakeJsonArraysOnly) {
  std::vector<int> classes = {0};
  ConfigRegistry r;
  r.Bind("detector.classes", &classes, "class ids");
  r.ApplyOverride("detector.classes=[0, 2, 7]");
  EXPECT_EQ(classes, (std::vector<int>{0, 2, 7}));
  r.Apply(nlohmann::json::parse(R"({"detector": {"classes": []}})"), "c.json");
  EXPECT_TRUE(classes.empty());
  EXPECT_NE(test::InputErrorOf([&] { r.ApplyOverride("detector.classes=3"); }).find("expects a list of integers, got 3"),
            std::string::npos);
  EXPECT_NE(test::InputErrorOf([&] { r.ApplyOverride("detector.classes=[1.5]"); }).find("expects an integer, got 1.5"),
            std::string::npos);
  EXPECT_EQ(r.ToJson()["detector"]["classes"], nlohmann::json::array());
}

TEST(ConfigRegistry, ToJsonEchoesEffectiveValues) {
  Fields f;
  ConfigRegistry r = Registry(&f);
  r.ApplyOverride("stage.count=5");
  const nlohmann::json j = r.ToJson();
  EXPECT_EQ(j["stage"]["count"], 5);
  EXPECT_EQ(j["other"]["mode"], "a");
  // The echo is itself a valid config.
  Fields g;
  ConfigRegistry r2 = Registry(&g);
  r2.Apply(j, "echo");
  EXPECT_EQ(g.count, 5);
  EXPECT_EQ(r.Describe().size(), 5u);
}

}  // namespace
}  // namespace dynvo
