// QEMU running a devboard ELF with its two serial streams on Unix sockets this process listens
// on: the ground UART (the 16550) and the sensor link (a virtio console, docs/devboard.md).
// Lock-step needs no virtual clock held to the wall: QEMU runs with -icount shift=0,sleep=off,
// so the board's instruction counter is exact and its time is whatever the simulator stamps.
#pragma once

#include <sys/types.h>

#include <stddef.h>
#include <stdint.h>

#include <string>

namespace qrsim {

class DevboardProcess {
 public:
  DevboardProcess() = default;
  DevboardProcess(const DevboardProcess&) = delete;
  DevboardProcess& operator=(const DevboardProcess&) = delete;
  ~DevboardProcess();

  // Starts QEMU with `elf` and waits (at most 10 s) until it has connected both streams; on
  // failure says why in `error`.
  // core_mhz > 0: the board's time runs on by its instructions at that speed while a tick runs
  // (docs/devboard.md, "A core of a given speed"); 0: it stands still.
  bool start(const std::string& elf, uint32_t core_mhz, std::string& error);

  int ground() const { return ground_fd_; }
  int link() const { return link_fd_; }
  // What QEMU printed (its errors), for a message when it died.
  std::string log() const;

 private:
  void stop();

  pid_t pid_ = -1;
  int ground_fd_ = -1;
  int link_fd_ = -1;
  std::string dir_;
};

// Writes all of `bytes`; false when the other end is gone.
bool write_all(int fd, const uint8_t* bytes, size_t size);
// Reads what is there, waiting at most `timeout_ms` for the first byte: the count, 0 on timeout,
// -1 when the other end is gone.
long read_some(int fd, uint8_t* bytes, size_t capacity, int timeout_ms);

}  // namespace qrsim
