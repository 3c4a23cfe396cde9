#include <pc/platform/log_folder.hpp>

#include <errno.h>
#include <sys/stat.h>
#include <time.h>

#include <cstdio>
#include <cstring>
#include <ctime>

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

}  // namespace qrterm
