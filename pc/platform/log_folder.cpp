#include <pc/platform/log_folder.hpp>

#include <errno.h>
#include <sys/stat.h>
#include <time.h>

#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>

#include <pc/core/log_retention.hpp>

namespace qrterm {

std::string default_log_folder() {
  const time_t now = ::time(nullptr);
  tm local{};
  ::localtime_r(&now, &local);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  return std::string("./logs/") + stamp;
}

void make_folders(const std::string& path) {
  if (path.empty()) throw LogFolderError("the log folder has no name");
  for (size_t slash = path.find('/', 1);; slash = path.find('/', slash + 1)) {
    const std::string part = path.substr(0, slash);
    if (::mkdir(part.c_str(), 0777) != 0 && errno != EEXIST) {
      throw LogFolderError("cannot make the log folder " + part + ": " + std::strerror(errno));
    }
    if (slash == std::string::npos) break;
  }
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)) throw LogFolderError(path + " is not a folder");
}

std::unique_ptr<std::ofstream> open_in(const std::string& folder, const std::string& name) {
  auto file = std::make_unique<std::ofstream>(folder + "/" + name, std::ios::binary | std::ios::trunc);
  if (!*file) return nullptr;
  return file;
}

bool rename_in(const std::string& folder, const std::string& from, const std::string& to) {
  return std::rename((folder + "/" + from).c_str(), (folder + "/" + to).c_str()) == 0;
}

std::unique_ptr<std::ofstream> start_again_in(const std::string& folder, const std::string& name,
                                              const std::string& previous) {
  std::rename((folder + "/" + name).c_str(), (folder + "/" + previous).c_str());
  return open_in(folder, name);
}

std::vector<std::string> folders_in(const std::string& parent) {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(parent, error)) {
    std::error_code kind;
    if (entry.is_directory(kind)) names.push_back(entry.path().filename().string());
  }
  return names;
}

size_t remove_old_log_folders(const std::string& session, size_t keep, std::string& failed) {
  const std::filesystem::path path(session);
  const std::string parent = path.parent_path().empty() ? "." : path.parent_path().string();
  size_t removed = 0;
  for (const std::string& name : log_folders_to_remove(folders_in(parent), path.filename().string(), keep)) {
    std::error_code error;
    std::filesystem::remove_all(std::filesystem::path(parent) / name, error);
    if (error) {
      failed += (failed.empty() ? "" : ", ") + parent + "/" + name + ": " + error.message();
    } else {
      ++removed;
    }
  }
  return removed;
}

}  // namespace qrterm
