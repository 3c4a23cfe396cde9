// A virtio console on one of QEMU virt's virtio-mmio slots (the modern interface, version 2):
// the devboard's end of the sensor link (docs/devboard.md). One receive and one transmit queue
// (port 0, no multiport), a few small buffers each, statically allocated.
//
// Why virtio rather than a second 16550 (pci-serial): QEMU hands a 16550 one byte per trip
// through its main loop when the receive trigger is one byte, and with a deeper trigger a frame's
// tail waits for the character timeout; a virtio buffer takes a whole frame per interrupt, and a
// frame out is one notify that QEMU writes out before the CPU goes on.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace rv32virt {

class VirtioConsole {
 public:
  // Looks for a console on the eight virtio-mmio slots and starts it; false when there is none
  // (the devboard without a simulator), and then nothing else may be called.
  bool start();

  // Hands every byte received to `on_byte`, then gives the buffers back to the device. Polled:
  // the device's interrupt is not used (virt_board.cpp says why).
  template <class OnByte>
  void receive(OnByte&& on_byte) {
    const uint8_t* bytes = nullptr;
    size_t length = 0;
    while (next_received(bytes, length)) {
      for (size_t i = 0; i < length; ++i) on_byte(bytes[i]);
      recycle_received();
    }
  }

  // Queues `length` bytes (at most kBufferBytes) for the simulator; waits for a transmit buffer
  // when all are in flight (QEMU writes each out when notified, so that wait is short).
  void send(const uint8_t* bytes, size_t length);

  static constexpr size_t kBufferBytes = 128;

 private:
  bool next_received(const uint8_t*& bytes, size_t& length);
  void recycle_received();

  uintptr_t base_ = 0;
  uint16_t rx_seen_ = 0;  // used-ring entries of the receive queue taken so far
  uint16_t tx_seen_ = 0;  // used-ring entries of the transmit queue reclaimed so far
  uint16_t tx_posted_ = 0;
};

}  // namespace rv32virt
