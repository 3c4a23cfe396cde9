#include <pc/core/console_log.hpp>

#include <cstdio>

namespace qrterm {

const char* severity_name(Severity severity) {
  constexpr const char* kNames[] = {"info", "WARNING", "ERROR", "qr"};
  return kNames[static_cast<size_t>(severity)];
}

std::string format_seconds(uint32_t time_ms) {
  char text[24];
  std::snprintf(text, sizeof text, "%4u.%03u", time_ms / 1000, time_ms % 1000);
  return text;
}

void ConsoleLog::add(uint32_t time_ms, Severity severity, std::string text) {
  // A line the same as the last (a key held at a gain's end of range) is counted on the screen
  // ("(x23)") instead of filling it; the file keeps every one with its time.
  if (!lines_.empty() && lines_.back().severity == severity && lines_.back().text == text) {
    LogLine& last = lines_.back();
    ++last.repeats;
    last.time_ms = time_ms;
    if (file_ != nullptr) {
      *file_ << format_seconds(time_ms) << ' ' << severity_name(severity) << ": " << text << '\n';
      file_->flush();
    }
    ++total_;
    return;
  }
  if (file_ != nullptr) {
    *file_ << format_seconds(time_ms) << ' ' << severity_name(severity) << ": " << text << '\n';
    // Flushed at once: a console log is read after something went wrong, perhaps a crash.
    file_->flush();
  }
  lines_.push_back({time_ms, severity, std::move(text)});
  while (lines_.size() > keep_) lines_.pop_front();
  ++total_;
}

const LogLine* ConsoleLog::find_last(const std::string& fragment) const {
  for (auto it = lines_.rbegin(); it != lines_.rend(); ++it) {
    if (it->text.find(fragment) != std::string::npos) return &*it;
  }
  return nullptr;
}

}  // namespace qrterm
