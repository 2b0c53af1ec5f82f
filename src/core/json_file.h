#pragma once
// JSON as dynvo reads its files (configs, camera.json): comments allowed, and a key repeated
// within one object is an error, where a plain parser would keep the last value silently.

#include <string>

#include <nlohmann/json.hpp>

namespace dynvo {

// Parses `text`; `source` (a file name) leads every message. Throws InputError
// "<source>: not valid JSON: ..." or "<source>: key 'a.b' appears twice".
nlohmann::json ParseJsonStrictly(const std::string& text, const std::string& source);

}  // namespace dynvo
