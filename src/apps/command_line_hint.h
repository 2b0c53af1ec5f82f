#pragma once
// "Did you mean ...?" for a command line argument the parser did not expect: every dynvo
// program (dynvo-cli, rpe, ate and the tools) adds it to its usage error.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/close_match.h"

namespace dynvo {

// After a failed parse of `app`: " (did you mean '--dataset'?)" for the first unexpected
// argument that is close to an option or subcommand of the (sub)command it was given to; ""
// when there is none.
inline std::string ClosestArgumentHint(CLI::App& app) {
  CLI::App* target = &app;
  while (!target->get_subcommands().empty()) target = target->get_subcommands().front();
  std::vector<std::string> names;
  for (const CLI::Option* option : target->get_options())
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  for (const CLI::App* sub : target->get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  for (const std::string& argument : target->remaining()) {
    const std::string word = argument.substr(0, argument.find('='));
    const std::string match = CloseMatch(word, names);
    if (!match.empty() && match != word) return " (did you mean '" + match + "'?)";
  }
  return "";
}

}  // namespace dynvo
