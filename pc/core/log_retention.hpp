// Which session log folders go (docs/console.md "Files"): every start makes a folder under ./logs,
// and a week of flying left hundreds. The console keeps the newest `keep` of the folders it named
// itself (a date and time, 20250131-142502), never the session's own and never a folder of any
// other name (one the pilot made, or named with --log-dir).
#pragma once

#include <stddef.h>

#include <string>
#include <vector>

namespace qrterm {

// The default number of session folders kept (--keep-logs).
inline constexpr size_t kLogFoldersKept = 20;

// "20250131-142502": the name default_log_folder() gives a session's folder.
bool is_session_folder_name(const std::string& name);

// Of `names` (the folders beside the session's), the session folders to remove so that `keep`
// remain with the current one among them: the oldest first (their names sort by time). keep 0:
// none is removed.
std::vector<std::string> log_folders_to_remove(std::vector<std::string> names, const std::string& current, size_t keep);

}  // namespace qrterm
