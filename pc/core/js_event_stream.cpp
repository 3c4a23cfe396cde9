#include <pc/core/js_event_stream.hpp>

#include <errno.h>
#include <unistd.h>

#include <cstring>

namespace qrterm {

JsEventStream::ReadResult JsEventStream::read_from(int fd, const std::function<void(const js_event&)>& deliver) {
  uint8_t buffer[sizeof(js_event) * 32];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n == 0) return ReadResult::lost;
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno == EAGAIN ? ReadResult::ok : ReadResult::lost;
    }
    for (ssize_t i = 0; i < n; ++i) {
      partial_[partial_length_++] = buffer[i];
      if (partial_length_ < sizeof(js_event)) continue;
      js_event event;
      std::memcpy(&event, partial_, sizeof event);  // the driver's own record, in host layout
      partial_length_ = 0;
      deliver(event);
    }
  }
}

}  // namespace qrterm
