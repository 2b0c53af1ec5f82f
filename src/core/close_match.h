#pragma once
// "Did you mean ...?": the valid name closest to a mistyped one.

#include <string>
#include <vector>

namespace dynvo {

// The candidate with the fewest single-character edits (insert, delete, substitute, swap of
// neighbours) from `word`, when that is at most max(2, a third of the word's length); ""
// when no candidate is that close. Ties go to the first candidate.
std::string CloseMatch(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace dynvo
