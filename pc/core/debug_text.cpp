#include <pc/core/debug_text.hpp>

namespace qrterm {

std::vector<std::string> DebugTextAssembler::add(const wire::DebugText& piece) {
  std::vector<std::string> done;
  for (size_t i = 0; i < piece.length(); ++i) {
    const char c = piece.text[i];
    if (c == '\n') {
      done.push_back(std::move(line_));
      line_.clear();
    } else if (c != '\r') {
      // Control characters would move the terminal's cursor: shown as '?'.
      line_ += (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) ? '?' : c;
      if (line_.size() >= kMaxLine) {
        done.push_back(std::move(line_));
        line_.clear();
      }
    }
  }
  return done;
}

}  // namespace qrterm
