#include <pc/core/log_retention.hpp>

#include <algorithm>

namespace qrterm {

bool is_session_folder_name(const std::string& name) {
  if (name.size() != 15 || name[8] != '-') return false;
  for (size_t i = 0; i < name.size(); ++i) {
    if (i != 8 && (name[i] < '0' || name[i] > '9')) return false;
  }
  return true;
}

std::vector<std::string> log_folders_to_remove(std::vector<std::string> names, const std::string& current,
                                               size_t keep) {
  if (keep == 0) return {};
  std::erase_if(names, [&](const std::string& name) { return name == current || !is_session_folder_name(name); });
  std::sort(names.begin(), names.end());
  // The current folder is one of the kept: the others may be keep - 1.
  const size_t others = keep - 1;
  if (names.size() <= others) return {};
  names.resize(names.size() - others);
  return names;
}

}  // namespace qrterm
