#pragma once
// A registry of config keys bound to fields of options structs. The one place where a JSON
// config or a `--set key=value` override meets the code: unknown keys and wrongly typed values
// are rejected with the key's name, and the effective values can be echoed back as JSON.

#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dynvo {

class ConfigRegistry {
 public:
  // Binds a dotted key ("dynamic_mask.erode_iterations") to a field. The registry must not
  // outlive the fields it is bound to.
  void Bind(const std::string& key, int* field, const std::string& help);
  void Bind(const std::string& key, unsigned* field, const std::string& help);
  void Bind(const std::string& key, double* field, const std::string& help);
  void Bind(const std::string& key, bool* field, const std::string& help);
  void Bind(const std::string& key, std::string* field, const std::string& help);
  // A JSON array of integers ("detector.classes": [0, 2]).
  void Bind(const std::string& key, std::vector<int>* field, const std::string& help);
  // An enum-like field stored by `set` after parsing a string, read back with `get`.
  void BindChoice(const std::string& key, std::vector<std::string> choices, std::function<std::string()> get,
                  std::function<void(const std::string&)> set, const std::string& help);

  // A key that is no longer bound: applying it fails with "key 'OLD_KEY' " + `note` (e.g. "is
  // now 'a.b'", "was retired: ...") instead of "unknown key".
  void NoteMoved(const std::string& old_key, const std::string& note);

  // Applies every leaf of a JSON object (nested objects form dotted keys; keys starting with
  // '_' are comments and skipped). Throws InputError
  // "<source>: unknown key 'a.b'" or "<source>: key 'a.b' expects <type>, got <value>".
  void Apply(const nlohmann::json& config, const std::string& source);
  // Applies one "key=value" override; the value is read as JSON when it parses (numbers,
  // true/false, quoted strings), as a plain string otherwise.
  void ApplyOverride(const std::string& assignment);

  // The effective values of every bound key as a nested JSON object.
  nlohmann::json ToJson() const;
  // One line per key: "key (type, default VALUE): help", in key order.
  std::vector<std::string> Describe() const;
  bool Has(const std::string& key) const { return entries_.count(key) != 0; }

 private:
  struct Entry {
    std::string type;  // "integer", "number", "boolean", "string", "one of ..."
    std::string help;
    std::function<nlohmann::json()> get;
    std::function<void(const nlohmann::json&, const std::string& where)> set;
  };
  void Add(const std::string& key, Entry entry);
  void ApplyValue(const std::string& key, const nlohmann::json& value, const std::string& source);

  std::map<std::string, Entry> entries_;
  std::map<std::string, std::string> moved_;  // old key -> what became of it
};

}  // namespace dynvo
