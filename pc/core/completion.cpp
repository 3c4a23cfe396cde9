#include <pc/core/completion.hpp>

namespace qrterm {

std::string last_word(const std::string& line) { return line.substr(line.find_last_of(' ') + 1); }

Completion complete_last_word(const std::string& line, const std::vector<std::string>& names) {
  Completion out{line, {}, names.empty()};
  if (names.empty()) return out;
  const std::string before = line.substr(0, line.size() - last_word(line).size());
  if (names.size() == 1) {
    out.text = before + names.front() + " ";
    return out;
  }
  std::string shared = names.front();
  for (const std::string& name : names) {
    size_t n = 0;
    while (n < shared.size() && n < name.size() && shared[n] == name[n]) ++n;
    shared.resize(n);
  }
  out.text = before + shared;
  out.candidates = names;
  return out;
}

}  // namespace qrterm

namespace qrterm {

std::string candidates_line(const std::vector<std::string>& names, size_t width) {
  std::string line;
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string next = (line.empty() ? "" : " ") + names[i];
    const size_t left = names.size() - i - 1;
    const std::string more = left == 0 ? "" : " (+" + std::to_string(left) + " more: type more)";
    // Room for this name and, if any follow, the note that says so.
    const std::string rest = " (+" + std::to_string(left + 1) + " more: type more)";
    if (line.size() + next.size() + more.size() > width) return line + (line.empty() ? rest.substr(1) : rest);
    line += next;
  }
  return line;
}

}  // namespace qrterm
