// The parts of log lines the console asked for again (log_resend), waiting to be sent. They go
// out before the download's next parts, so a part lost on a bad line costs one part and a short
// wait, while the stream goes on (docs/protocol.md section 8). A fixed ring of requests: a request
// that finds it full is refused (busy), and the console asks again later.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/requests.hpp>

namespace qr {

class LogRepairs {
 public:
  static constexpr uint8_t kSlots = 8;
  static constexpr size_t kBits = wire::kLogResendMaskBytes * 8;

  struct Part {
    wire::LogKind log;
    uint16_t line;
    uint8_t part;
  };

  bool add(const wire::LogResend& request) {
    if (count_ == kSlots) return false;
    slots_[(head_ + count_) % kSlots] = Slot{request, 0};
    ++count_;
    return true;
  }

  void clear() { head_ = count_ = 0; }
  bool empty() const { return count_ == 0; }

  // The oldest part still wanted, with `parts_per_line` the parts of a line of its log; false
  // when none is. Parts of lines at or past `lines(log)` are dropped on the way.
  template <class LinesOf>
  bool next(uint8_t (*parts_per_line)(wire::LogKind), LinesOf&& lines, Part& out) {
    while (count_ > 0) {
      Slot& s = slots_[head_];
      const uint8_t per_line = parts_per_line(s.request.log);
      for (; s.bit < kBits; ++s.bit) {
        if (!s.request.wants(s.bit)) continue;
        const uint32_t line = uint32_t{s.request.first_line} + s.bit / per_line;
        if (line >= lines(s.request.log)) continue;
        out = Part{s.request.log, static_cast<uint16_t>(line), static_cast<uint8_t>(s.bit % per_line)};
        return true;
      }
      head_ = static_cast<uint8_t>((head_ + 1) % kSlots);
      --count_;
    }
    return false;
  }
  // The part next() gave was sent.
  void sent() {
    if (count_ > 0) ++slots_[head_].bit;
  }

 private:
  struct Slot {
    wire::LogResend request;
    uint8_t bit;  // the next bit of the mask to look at
  };
  Slot slots_[kSlots] = {};
  uint8_t head_ = 0;
  uint8_t count_ = 0;
};

}  // namespace qr
