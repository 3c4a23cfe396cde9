#include <pc/core/settings_text.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace qrterm {
namespace {

std::string trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const size_t last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

bool is_name(const std::string& name) {
  if (name.empty()) return false;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) return false;
  }
  return true;
}

}  // namespace

SettingsText read_settings(const std::string& text) {
  SettingsText out;
  std::istringstream in(text);
  std::string raw;
  size_t number = 0;
  while (std::getline(in, raw)) {
    ++number;
    const std::string line = trim(raw.substr(0, raw.find('#')));
    if (line.empty()) continue;
    const size_t equals = line.find('=');
    if (equals == std::string::npos) {
      out.errors.push_back({number, "expected \"name = value\", found \"" + line + "\""});
      continue;
    }
    Setting setting{number, trim(line.substr(0, equals)), trim(line.substr(equals + 1))};
    if (!is_name(setting.name)) {
      out.errors.push_back({number, "\"" + setting.name + "\" is not a name (letters, digits and _ only)"});
    } else if (setting.value.empty()) {
      out.errors.push_back({number, "no value for " + setting.name});
    } else {
      out.settings.push_back(std::move(setting));
    }
  }
  return out;
}

std::string describe(const std::string& file, const std::vector<LineError>& errors) {
  std::string text;
  for (const LineError& error : errors) text += file + ":" + std::to_string(error.line) + ": " + error.message + "\n";
  return text;
}

bool read_file(const std::string& path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  text = buffer.str();
  return !in.bad();
}

std::string write_file_atomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".new";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) return "cannot write " + temporary + ": " + std::strerror(errno);
    out << text;
    out.flush();
    if (!out) return "cannot write " + temporary + ": " + std::strerror(errno);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(temporary.c_str());
    return "cannot replace " + path + ": " + why;
  }
  return "";
}

}  // namespace qrterm
