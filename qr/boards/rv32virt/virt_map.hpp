// Addresses of the QEMU `virt` machine's devices we use (QEMU hw/riscv/virt.c memory map).
#pragma once

#include <stdint.h>

namespace rv32virt::map {

// CLINT: machine timer. mtime counts at the timebase, 10 MHz on `virt`.
inline constexpr uintptr_t kClint = 0x02000000u;
inline constexpr uintptr_t kMtimecmp = kClint + 0x4000u;  // hart 0
inline constexpr uintptr_t kMtime = kClint + 0xBFF8u;
inline constexpr uint32_t kTimebaseHz = 10000000u;

// PLIC: external interrupts, context 0 = hart 0 machine mode.
inline constexpr uintptr_t kPlic = 0x0C000000u;
inline constexpr uintptr_t kPlicEnable = kPlic + 0x2000u;
inline constexpr uintptr_t kPlicThreshold = kPlic + 0x200000u;
inline constexpr uintptr_t kPlicClaim = kPlic + 0x200004u;

// UART0: NS16550A, interrupt source 10.
inline constexpr uintptr_t kUart = 0x10000000u;
inline constexpr uint32_t kUartIrq = 10;

// virtio-mmio: eight slots of 4 KiB (the sensor link's console is on whichever slot QEMU put it).
inline constexpr uintptr_t kVirtio = 0x10001000u;
inline constexpr uintptr_t kVirtioSlotBytes = 0x1000u;
inline constexpr uint32_t kVirtioSlots = 8;

// Where scripts/devboard has QEMU's generic loader put a sensor recording (RAM starts at
// 0x8000'0000; the program and its stack stay below 1 MiB).
inline constexpr uintptr_t kRecording = 0x80400000u;

// The core-speed word (docs/devboard.md, "A core of a given speed"): qrsim --core-mhz N has
// QEMU's generic loader put kCoreSpeedMagic and N here, in the last 8 bytes of virt's 128 MiB of
// RAM; without it the word reads 0 and the board keeps the simulator's time.
inline constexpr uintptr_t kCoreSpeed = 0x87FFFFF8u;
inline constexpr uint32_t kCoreSpeedMagic = 0x45524F43u;  // "CORE"

template <class T>
volatile T& reg(uintptr_t address) {
  return *reinterpret_cast<volatile T*>(address);
}

}  // namespace rv32virt::map
