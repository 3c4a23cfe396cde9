// The joystick device (/dev/input/jsN), opened non-blocking, with its reader. A device that goes
// away is closed and looked for again now and then, so a pilot who re-plugs it carries on.
#pragma once

#include <stdexcept>
#include <string>

#include <pc/core/joystick_reader.hpp>

namespace qrterm {

struct JoystickError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The device opened for its raw events: the joystick wizard reads them before there is a map.
class RawJoystick {
 public:
  // Throws JoystickError when the device cannot be opened.
  explicit RawJoystick(const std::string& path);
  ~RawJoystick();
  RawJoystick(const RawJoystick&) = delete;
  RawJoystick& operator=(const RawJoystick&) = delete;

  int fd() const { return fd_; }

 private:
  int fd_ = -1;
};

class JoystickDevice {
 public:
  // Throws JoystickError when the device cannot be opened.
  JoystickDevice(const std::string& path, const JoystickMap& map);
  ~JoystickDevice();
  JoystickDevice(const JoystickDevice&) = delete;
  JoystickDevice& operator=(const JoystickDevice&) = delete;

  int fd() const { return fd_; }
  const std::string& path() const { return path_; }
  JoystickReader& reader() { return reader_; }

  // Reads what is there; false when the device has gone (it is then closed).
  bool read();
  // Tries to open it again, with a fresh reader; true when it is back.
  bool reopen();

 private:
  std::string path_;
  JoystickMap map_;
  JoystickReader reader_;
  int fd_ = -1;
};

}  // namespace qrterm
