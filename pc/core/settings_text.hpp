// The "name = value" text both of the console's own files use (parameters, joystick map): one
// setting a line, '#' starts a comment, blank lines are fine. Reading keeps line numbers so that
// every complaint can say where the bad line is.
#pragma once

#include <stddef.h>

#include <string>
#include <vector>

namespace qrterm {

struct Setting {
  size_t line = 0;  // 1-based
  std::string name;
  std::string value;
};

// A problem with one line of a file, phrased for the person who wrote it.
struct LineError {
  size_t line = 0;
  std::string message;
};

struct SettingsText {
  std::vector<Setting> settings;
  std::vector<LineError> errors;  // lines that are not "name = value"
};

SettingsText read_settings(const std::string& text);

// "FILE:LINE: message", one a line.
std::string describe(const std::string& file, const std::vector<LineError>& errors);

// Whole file into a string; false if it cannot be read (errno is left set).
bool read_file(const std::string& path, std::string& text);

// Writes through a temporary file in the same folder and renames it over the old one, so an
// interrupted save never leaves half a file. Returns an empty string or what went wrong.
std::string write_file_atomically(const std::string& path, const std::string& text);

}  // namespace qrterm
