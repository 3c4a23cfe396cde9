#include <pc/platform/joystick_device.hpp>

#include <errno.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstring>

namespace qrterm {
namespace {

int open_device(const std::string& path) { return ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC); }

int open_or_throw(const std::string& path) {
  const int fd = open_device(path);
  if (fd < 0) throw JoystickError("no joystick at " + path + ": " + std::strerror(errno));
  return fd;
}

}  // namespace

RawJoystick::RawJoystick(const std::string& path) : fd_(open_or_throw(path)) {}

RawJoystick::~RawJoystick() { ::close(fd_); }

JoystickDevice::JoystickDevice(const std::string& path, const JoystickMap& map)
    : path_(path), map_(map), reader_(map), fd_(open_or_throw(path)) {}

JoystickDevice::~JoystickDevice() {
  if (fd_ >= 0) ::close(fd_);
}

bool JoystickDevice::read() {
  if (fd_ < 0) return false;
  if (reader_.read_from(fd_) == JoystickReader::ReadResult::ok) return true;
  ::close(fd_);
  fd_ = -1;
  return false;
}

bool JoystickDevice::reopen() {
  if (fd_ >= 0) return true;
  fd_ = open_device(path_);
  if (fd_ < 0) return false;
  reader_ = JoystickReader(map_);
  return true;
}

}  // namespace qrterm
