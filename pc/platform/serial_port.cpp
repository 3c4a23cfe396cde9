#include <pc/platform/serial_port.hpp>

#include <errno.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <cstring>

namespace qrterm {
namespace {

struct BaudRate {
  uint32_t baud;
  speed_t speed;
};

constexpr BaudRate kBaudRates[] = {
    {9600, B9600},     {19200, B19200},   {38400, B38400},   {57600, B57600},
    {115200, B115200}, {230400, B230400}, {460800, B460800}, {921600, B921600},
};

std::string system_error(const std::string& what) { return what + ": " + std::strerror(errno); }

}  // namespace

std::string SerialPort::supported_bauds() {
  std::string text;
  for (const BaudRate& rate : kBaudRates) text += (text.empty() ? "" : ", ") + std::to_string(rate.baud);
  return text;
}

SerialPort::SerialPort(const std::string& path, uint32_t baud) : path_(path) {
  const BaudRate* rate = nullptr;
  for (const BaudRate& candidate : kBaudRates) {
    if (candidate.baud == baud) rate = &candidate;
  }
  if (rate == nullptr)
    throw SerialError("baud rate " + std::to_string(baud) + " is not supported (" + supported_bauds() + ")");

  fd_ = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) {
    if (errno == EBUSY) throw SerialError(path + " is busy: another program has it open exclusively");
    if (errno == ENOENT)
      throw SerialError(system_error("cannot open " + path) + " (is the QR plugged in? is the path right?)");
    if (errno == EACCES)
      throw SerialError(system_error("cannot open " + path) + " (add yourself to the dialout group)");
    throw SerialError(system_error("cannot open " + path));
  }
  const auto fail = [this](const std::string& message) {
    ::close(fd_);
    fd_ = -1;
    throw SerialError(message);
  };
  termios tio{};
  if (::tcgetattr(fd_, &tio) != 0) fail(path + " is not a serial device (" + std::strerror(errno) + ")");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    fail(errno == EWOULDBLOCK ? path + " is busy: another program (another qrterm?) is using it"
                              : system_error("cannot lock " + path));
  }
  if (::ioctl(fd_, TIOCEXCL) != 0) fail(system_error("cannot take " + path + " for this program alone"));

  ::cfmakeraw(&tio);
  tio.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | PARENB | CRTSCTS | CSIZE);
  tio.c_cflag |= CS8 | CLOCAL | CREAD;
  // VMIN 1 with O_NONBLOCK: a read with nothing to read fails with EAGAIN, and a read of 0 bytes
  // means the line hung up. (With VMIN 0 both would read 0 bytes.)
  tio.c_cc[VMIN] = 1;
  tio.c_cc[VTIME] = 0;
  if (::cfsetispeed(&tio, rate->speed) != 0 || ::cfsetospeed(&tio, rate->speed) != 0 ||
      ::tcsetattr(fd_, TCSANOW, &tio) != 0) {
    fail(system_error("cannot configure " + path));
  }
  // Whatever waited in the buffers belongs to an earlier session.
  ::tcflush(fd_, TCIOFLUSH);
}

SerialPort::~SerialPort() {
  if (fd_ < 0) return;
  // Exclusive mode belongs to the device, not to our descriptor: a pty that the simulator or QEMU
  // keeps open would stay locked for the next console after we are gone.
  ::ioctl(fd_, TIOCNXCL);
  ::close(fd_);
}

SerialPort::Io SerialPort::read_available(std::vector<uint8_t>& into, std::string& why) {
  uint8_t buffer[512];
  for (;;) {
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n > 0) {
      into.insert(into.end(), buffer, buffer + n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN) return Io::ok;
    // A pty whose other end closed reads EIO; a vanished USB adapter reads 0 or ENODEV/EIO.
    why = n == 0 ? path_ + " was closed at the other end" : system_error(path_);
    return Io::closed;
  }
}

SerialPort::Io SerialPort::write_some(std::vector<uint8_t>& from, std::string& why) {
  while (!from.empty()) {
    const ssize_t n = ::write(fd_, from.data(), from.size());
    if (n > 0) {
      from.erase(from.begin(), from.begin() + n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN) return Io::ok;
    why = system_error(path_);
    return Io::closed;
  }
  return Io::ok;
}

}  // namespace qrterm
