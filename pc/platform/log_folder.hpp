// The folder a console session writes into (--log-dir, default ./logs/<date>-<time>/), and
// files in it.
#pragma once

#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

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

}  // namespace qrterm
