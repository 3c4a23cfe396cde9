#include <pc/platform/line_reader.hpp>

#include <errno.h>
#include <unistd.h>

namespace qrterm {

std::vector<std::string> LineReader::read(bool& open) {
  std::vector<std::string> lines;
  open = true;
  char buffer[1024];
  for (;;) {
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN) break;
    if (n <= 0) {
      open = false;
      if (!partial_.empty()) lines.push_back(std::move(partial_));
      partial_.clear();
      break;
    }
    partial_.append(buffer, static_cast<size_t>(n));
  }
  size_t start = 0;
  for (size_t end = partial_.find('\n'); end != std::string::npos; end = partial_.find('\n', start)) {
    lines.push_back(partial_.substr(start, end - start));
    start = end + 1;
  }
  partial_.erase(0, start);
  return lines;
}

}  // namespace qrterm
