// The sim board's I2C bus: the firmware's shared bus (common/drivers/i2c.hpp, I2cSharedBus, two
// channels: the sensor stage's MPU-6050 and MS5611) over the simulator's register-level chips
// (sim/i2c_device.hpp), with the wire's time in simulated time.
//
// The transfers begun run back to back in the order begun at 400 kHz: one starts when it is begun
// or when the one before it ends, whichever is later, and takes transfer_time_ns() (its bits at the
// bus clock). Each goes to the chip with its address (none: an address NACK, the reply's bytes
// 0xFF, the line's pull-up): write() with the instant its last written byte is acknowledged, then
// for a read read() with the instant the read address is. Its result is the channel's only once
// the wire has finished it: poll() says pending before. Time stands still while a tick runs, so a
// transfer begun by a tick is on the wire in the simulated time after the kick, and ended before
// the next one when the tick's transfers take less than a period (390 us for the MPU's burst,
// 142.5 us at most for the MS5611's: 532.5 us of the 1000).
//
// The transfer is played on the chips when it is begun, at the instants it will have on the wire:
// nothing the chips do between now and then depends on the world (the MPU's registers change only
// at the kicks; the MS5611's conversion senses at its middle, milliseconds after its command).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <array>
#include <vector>

#include <common/drivers/i2c.hpp>
#include <sim/i2c_device.hpp>
#include <sim/world.hpp>

namespace qrsim {

class SimI2cBus {
 public:
  static constexpr uint8_t kChannels = 2;
  static constexpr uint32_t kClockHz = 400000;

  explicit SimI2cBus(const sim::World& world) : world_(world) {}

  // A chip on the wire (it must outlive the bus).
  void attach(sim::I2cDevice& chip) { chips_.push_back(&chip); }

  // ---- drivers::I2cSharedBus ----
  bool begin(uint8_t channel, const drivers::I2cTransfer& transfer);
  drivers::I2cResult poll(uint8_t channel, drivers::I2cReply& reply);

  // Figures: the transfers run, the wire's busy time in all, the addresses nobody answered.
  uint64_t transfers() const { return transfers_; }
  uint64_t busy_ns() const { return busy_ns_; }
  uint64_t address_nacks() const { return address_nacks_; }

  // ---- the wire's faults (scenario events, docs/simulator.md section 6.2) ----
  // A transfer that starts on the wire within [from_us, until_us) of the world's clock: to
  // `address`, answered with an address NACK and nothing read (the chip browned out, a loose
  // connector); for a stuck SDA, to any address, `bus_stuck` (a device holds SDA low: no START can
  // be made; the reply's bytes read 0x00). kForever: to the end of the flight.
  static constexpr uint64_t kForever = UINT64_MAX;
  void nack_address(uint8_t address, uint64_t from_us, uint64_t until_us) {
    faults_.push_back({WireFault::nack, address, from_us * 1000, until_us == kForever ? kForever : until_us * 1000});
  }
  void stick_sda(uint64_t from_us, uint64_t until_us) {
    faults_.push_back({WireFault::stuck, 0, from_us * 1000, until_us == kForever ? kForever : until_us * 1000});
  }
  uint64_t fault_answers() const { return fault_answers_; }  // transfers a wire fault answered

 private:
  uint64_t now_ns() const { return world_.now_us() * 1000; }
  // The transfer on the wire from `start_ns`, answered by its chip.
  drivers::I2cResult run(const drivers::I2cTransfer& transfer, uint64_t start_ns, drivers::I2cReply& reply);
  sim::I2cDevice* chip(uint8_t address) const;
  // The wire fault acting on a transfer to `address` starting at `start_ns`, if any.
  enum class WireFault : uint8_t { nack, stuck };
  struct WireWindow {
    WireFault kind;
    uint8_t address;  // the NACK's; any for a stuck SDA
    uint64_t from_ns, until_ns;
  };
  const WireWindow* fault_at(uint8_t address, uint64_t start_ns) const;

  const sim::World& world_;
  std::vector<sim::I2cDevice*> chips_;
  drivers::I2cQueue<kChannels> queue_;
  std::array<uint64_t, kChannels> ready_at_ns_{};
  uint64_t wire_free_at_ns_ = 0;
  uint64_t transfers_ = 0;
  uint64_t busy_ns_ = 0;
  uint64_t address_nacks_ = 0;
  std::vector<WireWindow> faults_;
  uint64_t fault_answers_ = 0;
};

static_assert(drivers::I2cSharedBus<SimI2cBus>);

}  // namespace qrsim
