#include "core/config_registry.h"

#include <cmath>
#include <limits>

#include "core/close_match.h"
#include "core/error.h"
#include "core/json_file.h"

namespace dynvo {
namespace {

[[noreturn]] void TypeError(const std::string& where, const std::string& type, const nlohmann::json& value) {
  throw InputError(where + " expects " + type + ", got " + JsonText(value));
}

void Flatten(const nlohmann::json& node, const std::string& prefix,
             std::vector<std::pair<std::string, nlohmann::json>>* leaves) {
  if (node.is_object() && (prefix.empty() || !node.empty())) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      if (!it.key().empty() && it.key()[0] == '_') continue;  // "_comment" and the like
      Flatten(it.value(), prefix.empty() ? it.key() : prefix + "." + it.key(), leaves);
    }
    return;
  }
  leaves->emplace_back(prefix, node);
}

long long IntegerValue(const nlohmann::json& value, const std::string& where) {
  if (value.is_number_integer()) return value.get<long long>();
  if (value.is_number_float()) {
    const double d = value.get<double>();
    if (std::floor(d) == d && std::abs(d) < 1e15) return static_cast<long long>(d);
  }
  TypeError(where, "an integer", value);
}

}  // namespace

void ConfigRegistry::Add(const std::string& key, Entry entry) { entries_[key] = std::move(entry); }

void ConfigRegistry::Bind(const std::string& key, int* field, const std::string& help) {
  Add(key, {"integer", help, [field] { return nlohmann::json(*field); },
            [field](const nlohmann::json& v, const std::string& where) {
              const long long x = IntegerValue(v, where);
              if (x < std::numeric_limits<int>::min() || x > std::numeric_limits<int>::max())
                TypeError(where, "an integer in the int range", v);
              *field = static_cast<int>(x);
            }});
}

void ConfigRegistry::Bind(const std::string& key, unsigned* field, const std::string& help) {
  Add(key, {"non-negative integer", help, [field] { return nlohmann::json(*field); },
            [field](const nlohmann::json& v, const std::string& where) {
              const long long x = IntegerValue(v, where);
              if (x < 0 || x > std::numeric_limits<unsigned>::max()) TypeError(where, "a non-negative integer", v);
              *field = static_cast<unsigned>(x);
            }});
}

void ConfigRegistry::Bind(const std::string& key, double* field, const std::string& help) {
  Add(key, {"number", help, [field] { return nlohmann::json(*field); },
            [field](const nlohmann::json& v, const std::string& where) {
              if (!v.is_number()) TypeError(where, "a number", v);
              *field = v.get<double>();
            }});
}

void ConfigRegistry::Bind(const std::string& key, bool* field, const std::string& help) {
  Add(key, {"boolean", help, [field] { return nlohmann::json(*field); },
            [field](const nlohmann::json& v, const std::string& where) {
              if (!v.is_boolean()) TypeError(where, "true or false", v);
              *field = v.get<bool>();
            }});
}

void ConfigRegistry::Bind(const std::string& key, std::string* field, const std::string& help) {
  Add(key, {"string", help, [field] { return nlohmann::json(*field); },
            [field](const nlohmann::json& v, const std::string& where) {
              if (!v.is_string()) TypeError(where, "a string", v);
              *field = v.get<std::string>();
            }});
}

void ConfigRegistry::Bind(const std::string& key, std::vector<int>* field, const std::string& help) {
  Add(key, {"list of integers", help, [field] { return nlohmann::json(*field); },
            [field](const nlohmann::json& v, const std::string& where) {
              if (!v.is_array()) TypeError(where, "a list of integers", v);
              std::vector<int> values;
              for (const nlohmann::json& item : v) {
                const long long x = IntegerValue(item, where);
                if (x < std::numeric_limits<int>::min() || x > std::numeric_limits<int>::max())
                  TypeError(where, "a list of integers in the int range", v);
                values.push_back(static_cast<int>(x));
              }
              *field = values;
            }});
}

void ConfigRegistry::BindChoice(const std::string& key, std::vector<std::string> choices,
                                std::function<std::string()> get, std::function<void(const std::string&)> set,
                                const std::string& help) {
  std::string type = "one of";
  for (size_t i = 0; i < choices.size(); ++i) type += (i ? ", \"" : " \"") + choices[i] + "\"";
  Add(key, {type, help, [get] { return nlohmann::json(get()); },
            [choices, set, type](const nlohmann::json& v, const std::string& where) {
              if (!v.is_string()) TypeError(where, type, v);
              const std::string s = v.get<std::string>();
              for (const std::string& c : choices)
                if (c == s) return set(s);
              TypeError(where, type, v);
            }});
}

void ConfigRegistry::NoteMoved(const std::string& old_key, const std::string& note) { moved_[old_key] = note; }

void ConfigRegistry::ApplyValue(const std::string& key, const nlohmann::json& value, const std::string& source) {
  const auto it = entries_.find(key);
  if (it == entries_.end()) {
    const auto moved = moved_.find(key);
    if (moved != moved_.end()) throw InputError(source + ": key '" + key + "' " + moved->second);
    // The closest key first, then the keys of the same section, which is where typos usually are.
    std::vector<std::string> keys;
    std::string hint;
    const std::string section = key.substr(0, key.find('.'));
    for (const auto& [known, entry] : entries_) {
      keys.push_back(known);
      if (known.rfind(section + ".", 0) == 0) hint += (hint.empty() ? "" : ", ") + known;
    }
    const std::string closest = CloseMatch(key, keys);
    throw InputError(source + ": unknown key '" + key + "'" +
                     (closest.empty() ? "" : ", did you mean '" + closest + "'?") +
                     (hint.empty() ? "" : " (keys of '" + section + "': " + hint + ")"));
  }
  it->second.set(value, source + ": key '" + key + "'");
}

void ConfigRegistry::Apply(const nlohmann::json& config, const std::string& source) {
  if (!config.is_object()) throw InputError(source + ": the config must be a JSON object");
  std::vector<std::pair<std::string, nlohmann::json>> leaves;
  Flatten(config, "", &leaves);
  for (const auto& [key, value] : leaves) ApplyValue(key, value, source);
}

void ConfigRegistry::ApplyOverride(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) throw InputError("--set '" + assignment + "': expected key=value");
  const std::string key = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  nlohmann::json value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) value = text;
  ApplyValue(key, value, "--set");
}

nlohmann::json ConfigRegistry::ToJson() const {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [key, entry] : entries_)
    out[nlohmann::json::json_pointer("/" + [&] {
      std::string p = key;
      for (char& c : p)
        if (c == '.') c = '/';
      return p;
    }())] = entry.get();
  return out;
}

std::vector<std::string> ConfigRegistry::Describe() const {
  std::vector<std::string> lines;
  for (const auto& [key, entry] : entries_)
    lines.push_back(key + " (" + entry.type + ", default " + JsonText(entry.get()) + "): " + entry.help);
  return lines;
}

}  // namespace dynvo
