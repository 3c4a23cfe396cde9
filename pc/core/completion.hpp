// Tab on a line of names (the plot's observables), as a shell completes a word: the last word is
// completed when one name fits; when several do, it grows to the longest start they share and the
// candidates are listed, so the pilot sees what to type next.
#pragma once

#include <string>
#include <vector>

namespace qrterm {

struct Completion {
  std::string text;                     // the line after Tab
  std::vector<std::string> candidates;  // the names the last word may still become (empty: one or none fit)
  bool none = false;                    // no name starts with the last word
};

// `names`: every name that starts with the line's last word, in the order to list them.
Completion complete_last_word(const std::string& line, const std::vector<std::string>& names);

// The last word of a line (what `names` must start with): after its last space.
std::string last_word(const std::string& line);

}  // namespace qrterm

namespace qrterm {

// The candidates on one row of `width` characters, in order: "phi phi_sp phi_err", or as many as
// fit and "(+12 more: type more)" so a cut list does not pass for the whole of it.
std::string candidates_line(const std::vector<std::string>& names, size_t width);

}  // namespace qrterm
