#pragma once
// JSON as dynvo reads its files (configs, camera.json): comments allowed, and a key repeated
// within one object is an error, where a plain parser would keep the last value silently.

#include <string>

#include <nlohmann/json.hpp>

namespace dynvo {

// Parses `text`; `source` (a file name) leads every message. Throws InputError
// "<source>: not valid JSON: ..." or "<source>: key 'a.b' appears twice".
nlohmann::json ParseJsonStrictly(const std::string& text, const std::string& source);

// `value` as compact JSON text for a message or a file, never a throw: bytes that are not
// UTF-8 (a path given with --set may hold any) are written as U+FFFD.
std::string JsonText(const nlohmann::json& value, int indent = -1);

}  // namespace dynvo
