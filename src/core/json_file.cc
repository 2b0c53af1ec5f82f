#include "core/json_file.h"

#include <set>
#include <vector>

#include "core/error.h"

namespace dynvo {
namespace {

// An object or array being parsed: the keys seen in it and its dotted path.
struct OpenValue {
  std::set<std::string> keys;
  std::string path;
};

}  // namespace

std::string JsonText(const nlohmann::json& value, int indent) {
  return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

nlohmann::json ParseJsonStrictly(const std::string& text, const std::string& source) {
  using nlohmann::json;
  std::vector<OpenValue> open;
  std::string last_path;  // path of the last key: the name of the value that follows it
  const json::parser_callback_t check_keys = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        open.push_back({{}, open.empty() ? std::string() : last_path});
        break;
      case json::parse_event_t::key: {
        const std::string key = parsed.get<std::string>();
        OpenValue& object = open.back();
        last_path = object.path.empty() ? key : object.path + "." + key;
        if (!object.keys.insert(key).second) throw InputError(source + ": key '" + last_path + "' appears twice");
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        open.pop_back();
        break;
      case json::parse_event_t::value:
        break;
    }
    return true;
  };
  try {
    return json::parse(text, check_keys, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for a number like 1e309
    throw InputError(source + ": not valid JSON: " + e.what());
  }
}

}  // namespace dynvo
