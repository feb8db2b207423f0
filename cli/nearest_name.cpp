// "Did you mean" (see nearest_name.h).
#include "cli/nearest_name.h"

#include <algorithm>

namespace mbk::cli {
namespace {

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string nearest_name(const std::string& typed, const std::vector<std::string>& names) {
  std::string best;
  size_t best_distance = std::string::npos;
  for (const std::string& name : names)
    if (const size_t d = edit_distance(typed, name); d < best_distance) {
      best = name;
      best_distance = d;
    }
  // A typo changes a letter or two, more in a long name.
  if (!best.empty() && best_distance <= std::max<size_t>(1, typed.size() / 3)) return best;
  std::vector<std::string> extended;
  for (const std::string& name : names)
    if (typed.size() >= 3 && name.compare(0, typed.size(), typed) == 0) extended.push_back(name);
  return extended.size() == 1 ? extended[0] : "";
}

}  // namespace mbk::cli
