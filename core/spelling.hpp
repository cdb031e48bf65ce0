#pragma once
// "Did you mean": the name a mistyped word was most likely meant to be, for error messages
// about unknown commands, options and keys.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace covsim {

// Edits (insertions, deletions, substitutions, swaps of neighbours) between two words.
std::size_t spelling_distance(std::string_view a, std::string_view b);
// The names closest to `word` among those close enough to be a typo of it (at most one edit
// per three letters, at least one), in the order given; none if `word` is one of them.
std::vector<std::string> closest_spellings(std::string_view word,
                                           const std::vector<std::string>& names);
// The name closest to `word`, if one is close enough to be a typo of it and no other is as
// close.
std::optional<std::string> closest_spelling(std::string_view word,
                                            const std::vector<std::string>& names);

}  // namespace covsim
