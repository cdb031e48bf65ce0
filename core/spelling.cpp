#include "core/spelling.hpp"

#include <algorithm>

namespace covsim {

std::size_t spelling_distance(std::string_view a, std::string_view b) {
  // Optimal string alignment: Levenshtein with transpositions of adjacent letters, rows
  // i - 2, i - 1 and i kept.
  const std::size_t n = b.size();
  std::vector<std::size_t> before(n + 1), previous(n + 1), current(n + 1);
  for (std::size_t j = 0; j <= n; ++j)
    previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= n; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    before.swap(previous);
    previous.swap(current);
  }
  return previous[n];
}

std::vector<std::string> closest_spellings(std::string_view word,
                                           const std::vector<std::string>& names) {
  const std::size_t allowed = std::max<std::size_t>(1, word.size() / 3);
  std::vector<std::string> best;
  std::size_t best_distance = allowed + 1;
  for (const std::string& name : names) {
    const std::size_t d = spelling_distance(word, name);
    if (d == 0) return {};  // the word itself: no typo
    if (d < best_distance) {
      best = {name};
      best_distance = d;
    } else if (d == best_distance && std::find(best.begin(), best.end(), name) == best.end()) {
      best.push_back(name);
    }
  }
  return best;
}

std::optional<std::string> closest_spelling(std::string_view word,
                                            const std::vector<std::string>& names) {
  const std::vector<std::string> best = closest_spellings(word, names);
  if (best.size() != 1) return std::nullopt;
  return best.front();
}

}  // namespace covsim
