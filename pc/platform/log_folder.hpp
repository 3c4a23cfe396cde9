// The folder a console session writes into (--log-dir, default ./logs/<date>-<time>/), and
// files in it.
#pragma once

#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace qrterm {

struct LogFolderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "./logs/20250131-142502"; the seconds keep two sessions in one minute apart.
std::string default_log_folder();

// Creates the folder and its parents; throws LogFolderError naming what failed.
void make_folders(const std::string& path);

// A new file in the folder; null when it cannot be created.
std::unique_ptr<std::ofstream> open_in(const std::string& folder, const std::string& name);

// Renames a file in the folder; false when it could not.
bool rename_in(const std::string& folder, const std::string& from, const std::string& to);

// A file of the folder started again: `name` becomes `previous` (replacing the one before) and a
// fresh `name` is opened (null when it cannot be). rx.hex -> rx.hex.1, as logrotate names them.
std::unique_ptr<std::ofstream> start_again_in(const std::string& folder, const std::string& name,
                                              const std::string& previous);

// The sub-folders of `parent` (names only; none when it cannot be read).
std::vector<std::string> folders_in(const std::string& parent);

// The session folders beside `session` (a default folder, ./logs/<date>-<time>) beyond the newest
// `keep` removed with their files (log_retention.hpp); how many went. A folder that cannot be
// removed is left, and `failed` says which.
size_t remove_old_log_folders(const std::string& session, size_t keep, std::string& failed);

}  // namespace qrterm
