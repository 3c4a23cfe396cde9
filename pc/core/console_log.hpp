// The scrolling log on the screen and in console.log: what the console did (green), what needs
// the pilot's eye (yellow), what went wrong (red), and the QR's own debug text (cyan).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <deque>
#include <ostream>
#include <string>

namespace qrterm {

enum class Severity : uint8_t { info, warning, error, qr };

struct LogLine {
  uint32_t time_ms = 0;  // since the console started
  Severity severity = Severity::info;
  std::string text;
  uint32_t repeats = 0;  // the same line again right after: counted, not added (a held key)
};

// A line for the log, from a part that does not write it itself.
struct Notice {
  Severity severity = Severity::info;
  std::string text;
};

class ConsoleLog {
 public:
  // Keeps the newest `keep` lines for the screen; `file` (may be null) gets every line.
  explicit ConsoleLog(size_t keep = 500, std::ostream* file = nullptr) : keep_(keep), file_(file) {}

  void set_file(std::ostream* file) { file_ = file; }

  void add(uint32_t time_ms, Severity severity, std::string text);

  const std::deque<LogLine>& lines() const { return lines_; }
  // Lines ever added: the screen compares it to know whether to redraw.
  uint64_t total() const { return total_; }
  // The newest line with this text fragment, for tests and for the screen's banner; null if none.
  const LogLine* find_last(const std::string& fragment) const;

 private:
  size_t keep_;
  std::ostream* file_;
  std::deque<LogLine> lines_;
  uint64_t total_ = 0;
};

const char* severity_name(Severity severity);

// "  12.345" seconds, as the log file and the screen show times.
std::string format_seconds(uint32_t time_ms);

}  // namespace qrterm
