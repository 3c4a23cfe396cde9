// struct js_event records (the Linux joystick API, <linux/joystick.h>) out of a non-blocking
// descriptor. A read may end inside a record, so the part read is kept for the next one. Both the
// joystick reader (flying) and the joystick wizard read through it; tests feed it through a pipe.
#pragma once

#include <linux/joystick.h>
#include <stddef.h>
#include <stdint.h>

#include <functional>

namespace qrterm {

class JsEventStream {
 public:
  enum class ReadResult : uint8_t {
    ok,    // read what there was (maybe nothing)
    lost,  // end of file or a read error: the device is gone (unplugged)
  };

  // Reads every record available and hands each to `deliver`, in the order the driver sent them.
  ReadResult read_from(int fd, const std::function<void(const js_event&)>& deliver);

 private:
  uint8_t partial_[sizeof(js_event)] = {};  // a record cut in two by a read
  size_t partial_length_ = 0;
};

}  // namespace qrterm
