// The QR's serial line: a real UART adapter (/dev/ttyUSB0) or any pty (the simulator, the QEMU
// devboard). Raw 8N1, no flow control, non-blocking, and ours alone: a second console on the same
// port would interleave its control messages with ours, so the port is locked (flock) and put in
// exclusive mode (TIOCEXCL).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace qrterm {

// Why a port could not be used, phrased for the pilot.
struct SerialError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr uint32_t kDefaultBaud = 115200;

class SerialPort {
 public:
  // Throws SerialError: no such device, busy, not a serial device, unsupported baud rate.
  SerialPort(const std::string& path, uint32_t baud);
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  int fd() const { return fd_; }
  const std::string& path() const { return path_; }

  enum class Io : uint8_t { ok, closed };

  // Appends what is there to `into`; `closed` when the other end is gone (hang-up, unplugged).
  Io read_available(std::vector<uint8_t>& into, std::string& why);
  // Writes what the line takes now and erases it from `from`.
  Io write_some(std::vector<uint8_t>& from, std::string& why);

  // The baud rates the port accepts, for the usage text.
  static std::string supported_bauds();

 private:
  int fd_ = -1;
  std::string path_;
};

}  // namespace qrterm
