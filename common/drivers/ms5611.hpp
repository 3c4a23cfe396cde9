// The MS5611 barometer on the I2C bus (i2c.hpp): its commands, the PROM's check, the datasheet's
// compensation in integers, and a driver stepped once per tick that never waits on the wire.
//
// The chip knows five commands, each one byte written on its own (address 0x77 with CSB low,
// 0x76 with CSB high: the address is 111011C, C the complement of CSB):
//
//   0x1E          reset: reloads the PROM into the chip's registers (2.8 ms)
//   0xA0 + 2 i    PROM word i (i = 0..7), read as two bytes, most significant first
//   0x40 + 2 k    convert D1 (pressure) at OSR 256 << k (k = 0..4: 0x40, 0x42, ... 0x48)
//   0x50 + 2 k    convert D2 (temperature) at OSR 256 << k (0x50 ... 0x58)
//   0x00          read the ADC: the last conversion's 24 bits, most significant first
//
// The datasheet draws a PROM or ADC read as the command with a STOP and then a read; we read
// with a repeated START after the command (one transfer, read_registers()), as register reads
// are made on this bus and as Linux's ms5611_i2c reads it.
//
// A conversion runs in the chip after its command; reading the ADC before it has finished gives
// 0 and spoils the conversion, and a new command during one spoils it too. So the driver reads
// only once the datasheet's maximum conversion time (kMs5611Osr below) has passed since it saw the
// command's transfer complete (it sees that at a tick at or after the end of the command on the
// wire, and the chip starts converting on the command byte, before it), and after any fault it
// lets one conversion time pass before the next command. On a shared bus (i2c.hpp's I2cQueue) a
// command may wait behind another driver's transfer: still counted from the end the driver sees.
//
// PROM: word 0 is the factory's, words 1..6 are C1..C6, the low four bits of word 7 are a CRC-4
// over the 8 words (application note AN520's procedure: the 16 bytes most significant first, word
// 7's low byte taken as 0, remainder polynomial 0x3000 in a 16-bit register, i.e. x^4 + x + 1;
// the CRC is bits 15..12 of the remainder). So bits 7..4 of word 7 are not covered by it.
//
// Compensation (datasheet, "Pressure and temperature calculation" and "Second order temperature
// compensation"), with TEMP in 0.01 C and P in 0.01 mbar = 1 Pa:
//
//   dT   = D2 - C5 * 2^8                          TEMP = 2000 + dT * C6 / 2^23
//   OFF  = C2 * 2^16 + (C4 * dT) / 2^7            SENS = C1 * 2^15 + (C3 * dT) / 2^8
//   below 20 C:  T2 = dT^2 / 2^31, OFF2 = 5 (TEMP - 2000)^2 / 2, SENS2 = 5 (TEMP - 2000)^2 / 4
//   below -15 C: OFF2 += 7 (TEMP + 1500)^2,        SENS2 += 11 (TEMP + 1500)^2 / 2
//   TEMP -= T2, OFF -= OFF2, SENS -= SENS2;       P = (D1 * SENS / 2^21 - OFF) / 2^15
//
// Every "/ 2^n" is an arithmetic shift here, a floor: the datasheet's division wherever the operand
// is positive (as in its worked example), at most one count lower where it is negative. The worked
// example: C1..C6 = 40127, 36924, 23317, 23282, 33464, 28312, D1 = 9085466, D2 = 8569150 give
// dT = 2366, TEMP = 2007 (20.07 C), OFF = 2420281617, SENS = 1315097036, P = 100009 Pa.
// The largest intermediate is D1 * SENS, 58 bits: the arithmetic is int64.
//
// Cost: four 64-bit multiplications (three more below 20 C) and shifts, no division. On RV32IM GCC
// does them inline (mul/mulhu, no libgcc call): `compensate` is 232 instructions long in the rv32
// preset's build (objdump; -O2 gives the same), 24 of them multiplications; from 20 C up it runs
// about 135 of them, below 20 C about 215 (counted along the disassembly, not measured). It runs
// once per pressure reading: 67 a second with the default configuration at a 1 kHz tick.
//
// Sources (facts, no code copied): MEAS / TE Connectivity, "MS5611-01BA03 Barometric Pressure
// Sensor, with stainless steel cap" datasheet (commands, addresses, the reset's 2.8 ms, ADC
// conversion times by OSR, the calculation figure with its ranges and worked example, the
// second-order compensation, a read of 0 when no conversion was done); TE / MEAS application note
// AN520 "C-code example for MS56xx, MS57xx (except analog sensor), and MS58xx series pressure
// sensors" (the CRC-4).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/drivers/i2c.hpp>

namespace drivers {

inline constexpr uint8_t kMs5611AddressCsbLow = 0x77;
inline constexpr uint8_t kMs5611AddressCsbHigh = 0x76;

inline constexpr uint8_t kMs5611Reset = 0x1E;
inline constexpr uint8_t kMs5611ConvertD1 = 0x40;  // + the OSR's offset
inline constexpr uint8_t kMs5611ConvertD2 = 0x50;  // + the OSR's offset
inline constexpr uint8_t kMs5611AdcRead = 0x00;
inline constexpr uint8_t kMs5611PromRead = 0xA0;  // + 2 x the word's index
inline constexpr uint8_t kMs5611PromWords = 8;
inline constexpr uint8_t kMs5611AdcBytes = 3;

// The PROM's reload after a reset (datasheet: reset sequence, 2.8 ms).
inline constexpr uint32_t kMs5611ResetTimeUs = 2800;

enum class Ms5611Osr : uint8_t { osr256, osr512, osr1024, osr2048, osr4096 };

struct Ms5611OsrRow {
  Ms5611Osr osr;
  uint16_t ratio;
  uint8_t command_offset;  // added to kMs5611ConvertD1 / kMs5611ConvertD2
  uint16_t conversion_us;  // the datasheet's maximum ADC conversion time
};

// Datasheet, "Operating conditions", ADC conversion time (max): 0.60, 1.17, 2.28, 4.54, 9.04 ms.
inline constexpr Ms5611OsrRow kMs5611Osr[] = {
    {Ms5611Osr::osr256, 256, 0x00, 600},    {Ms5611Osr::osr512, 512, 0x02, 1170},
    {Ms5611Osr::osr1024, 1024, 0x04, 2280}, {Ms5611Osr::osr2048, 2048, 0x06, 4540},
    {Ms5611Osr::osr4096, 4096, 0x08, 9040},
};
static_assert(sizeof(kMs5611Osr) / sizeof(kMs5611Osr[0]) == static_cast<size_t>(Ms5611Osr::osr4096) + 1,
              "one row per oversampling ratio");

constexpr const Ms5611OsrRow& ms5611_osr_row(Ms5611Osr osr) {
  const size_t i = static_cast<size_t>(osr);
  return kMs5611Osr[i < sizeof(kMs5611Osr) / sizeof(kMs5611Osr[0]) ? i : 0];
}

// What each transfer costs on the wire at 400 kHz (i2c.hpp), for a board that adds up its bus.
inline constexpr uint32_t kMs5611BusHz = 400000;
inline constexpr uint32_t kMs5611CommandNs = transfer_time_ns(write_command(kMs5611AddressCsbLow, kMs5611Reset),
                                                              kMs5611BusHz);  // 20 bits, 50 us
inline constexpr uint32_t kMs5611PromWordNs = transfer_time_ns(read_registers(kMs5611AddressCsbLow, kMs5611PromRead, 2),
                                                               kMs5611BusHz);  // 48 bits, 120 us
inline constexpr uint32_t kMs5611AdcReadNs = transfer_time_ns(
    read_registers(kMs5611AddressCsbLow, kMs5611AdcRead, kMs5611AdcBytes),
    kMs5611BusHz);  // 57 bits, 142.5 us

struct Ms5611Prom {
  uint16_t word[kMs5611PromWords] = {};  // word[1..6] are C1..C6; word[7] bits 3..0 the CRC
};

// AN520's CRC-4 of the eight PROM words (word 7's low byte read as 0).
constexpr uint8_t ms5611_crc4(const uint16_t prom[kMs5611PromWords]) {
  uint32_t remainder = 0;
  for (uint32_t byte = 0; byte < 2u * kMs5611PromWords; ++byte) {
    uint32_t word = prom[byte / 2];
    if (byte / 2 == kMs5611PromWords - 1) word &= 0xFF00u;
    remainder ^= (byte % 2 == 0) ? (word >> 8) : (word & 0xFFu);
    for (int bit = 0; bit < 8; ++bit) {
      remainder = (remainder & 0x8000u) ? ((remainder << 1) ^ 0x3000u) : (remainder << 1);
      remainder &= 0xFFFFu;
    }
  }
  return static_cast<uint8_t>((remainder >> 12) & 0xFu);
}

// The PROM as it may be used: its CRC matches, and it is not all zeros (a bus reading zeros
// would pass the CRC, whose remainder of nothing is 0).
constexpr bool ms5611_prom_valid(const Ms5611Prom& prom) {
  bool any = false;
  for (uint16_t w : prom.word) any = any || w != 0;
  return any && ms5611_crc4(prom.word) == (prom.word[kMs5611PromWords - 1] & 0xFu);
}

// The same PROM with its CRC nibble written in (tests, the simulator's chip).
constexpr Ms5611Prom ms5611_prom_with_crc(Ms5611Prom prom) {
  prom.word[7] = static_cast<uint16_t>((prom.word[7] & 0xFFF0u) | ms5611_crc4(prom.word));
  return prom;
}

// What the datasheet's calculation figure allows: D1 and D2 are 24-bit (0 is a read too early),
// TEMP -40..85 C, P 10..1200 mbar.
inline constexpr uint32_t kMs5611AdcMax = 0xFFFFFF;
inline constexpr int32_t kMs5611TempMinCentiC = -4000;
inline constexpr int32_t kMs5611TempMaxCentiC = 8500;
inline constexpr int32_t kMs5611PressureMinPa = 1000;
inline constexpr int32_t kMs5611PressureMaxPa = 120000;

struct Ms5611Reading {
  int32_t dt = 0;            // D2 - C5 * 2^8
  int32_t temp_centi_c = 0;  // TEMP after the second order, 0.01 C
  int64_t off = 0;           // OFF after the second order
  int64_t sens = 0;          // SENS after the second order
  int32_t pressure_pa = 0;   // P, 0.01 mbar = 1 Pa
  int32_t t2 = 0;            // the second-order terms taken off (0 from 20 C up)
  int64_t off2 = 0;
  int64_t sens2 = 0;
  bool in_range = false;  // D1, D2 in 1..2^24-1, TEMP and P within the ranges above
};

// First-order TEMP in 0.01 C from D2 (D2 at most 2^24 - 1).
constexpr int32_t ms5611_first_order_temp(const Ms5611Prom& prom, uint32_t d2) {
  const int64_t dt = static_cast<int64_t>(d2) - (static_cast<int64_t>(prom.word[5]) << 8);
  return static_cast<int32_t>(2000 + ((dt * prom.word[6]) >> 23));
}

// The datasheet's compensation, first and second order. D1 or D2 outside 1..2^24-1 computes
// nothing (all zeros, not in range).
Ms5611Reading compensate(const Ms5611Prom& prom, uint32_t d1, uint32_t d2);

// The faults the driver counts, each its own row.
enum class Ms5611Fault : uint8_t {
  address_nack,  // nobody answered the address (no chip, a wrong CSB)
  data_nack,     // the chip refused a byte
  bus_stuck,     // SDA held low
  bad_reply,     // "ok" with fewer bytes than asked for, or a result the bus forgot (idle)
  prom_crc,      // the PROM failed its CRC (or read all zeros)
  adc_zero,      // the ADC read 0: read too early, or no conversion was done
  out_of_range,  // a temperature or pressure the datasheet's ranges do not allow
  count_,
};
inline constexpr const char* kMs5611FaultNames[] = {"address_nack", "data_nack", "bus_stuck",   "bad_reply",
                                                    "prom_crc",     "adc_zero",  "out_of_range"};
static_assert(sizeof(kMs5611FaultNames) / sizeof(kMs5611FaultNames[0]) == static_cast<size_t>(Ms5611Fault::count_),
              "one name per fault");

enum class Ms5611State : uint8_t {
  starting,    // reset sent, or the PROM being read
  measuring,   // the PROM is good: conversions run and readings come
  prom_bad,    // the PROM failed its check: no conversions, no readings; a reset after the delay
  restarting,  // a fault at start-up, or kMs5611FaultsBeforeRestart faults in a row while
               // measuring: no readings; a reset after the delay
};

// Before a reset is tried again. A PROM spoilt on the way by a glitch reads right the next time;
// a chip that NACKs or a PROM that is really damaged will fail every time, and once a second
// their reset and eight PROM reads cost 1 ms of bus a second (0.1 %), so the IMU's transfers do
// not starve; meanwhile there is no barometer, which the state and the counts say.
inline constexpr uint32_t kMs5611RestartDelayUs = 1000000;
// Faults in a row (without a reading between) while measuring before the driver starts over with
// a reset: a chip that browned out has lost its PROM registers, and a PROM that passed its CRC by
// chance (1 in 16 for a random corruption) gives readings out of range until it is read again.
inline constexpr uint8_t kMs5611FaultsBeforeRestart = 8;

struct Ms5611Config {
  uint8_t address = kMs5611AddressCsbLow;
  Ms5611Osr osr = Ms5611Osr::osr4096;
  // D1 conversions per D2. The die's temperature changes over seconds, so a D2 some tens of
  // milliseconds old compensates as well as a fresh one, while every conversion spent on D1 is a
  // pressure for the height estimate. At OSR 4096 and a 1 kHz tick a conversion takes 12 ticks (its
  // command's end seen a tick later, 9.04 ms, the read's end a tick later): 1 gives 41 pressures a
  // second, 4 gives 67 (Ms5611Driver.ReadingsASecondAtA1kHzTick). 0 is taken as 1.
  uint8_t pressures_per_temperature = 4;
};

class Ms5611 {
 public:
  constexpr explicit Ms5611(const Ms5611Config& config = {})
      : config_(config), conversion_us_(ms5611_osr_row(config.osr).conversion_us) {
    if (config_.pressures_per_temperature == 0) config_.pressures_per_temperature = 1;
  }

  // Once per tick with the time in microseconds (wrapping): collects the transfer on the wire if
  // it has finished, then begins the next one if its time has come. Never waits.
  template <I2cBus Bus>
  void step(Bus& bus, uint32_t now_us) {
    if (on_wire_) {
      I2cReply reply;
      const I2cResult result = bus.poll(reply);
      if (result == I2cResult::pending) return;
      finished(result, reply, now_us);
    }
    I2cTransfer transfer;
    if (!next_transfer(now_us, transfer)) return;
    if (bus.begin(transfer)) {
      begun();
    } else {
      ++bus_busy_;  // another driver's transfer is on the bus: next tick
    }
  }

  Ms5611State state() const { return state_; }
  const Ms5611Prom& prom() const { return prom_; }

  // Readings: a counter that grows by one with each, the last one, and the time its pressure
  // conversion's command was seen complete (the pressure is of the conversion time after it).
  uint32_t readings() const { return readings_; }
  const Ms5611Reading& reading() const { return reading_; }
  uint32_t reading_time_us() const { return reading_time_us_; }
  // True once per new reading, with it.
  bool take(Ms5611Reading& out) {
    if (taken_ == readings_) return false;
    taken_ = readings_;
    out = reading_;
    return true;
  }

  uint32_t faults(Ms5611Fault fault) const { return faults_[static_cast<size_t>(fault)]; }
  uint32_t total_faults() const;
  // The kind of the last fault counted (Ms5611Fault::count_ before the first).
  Ms5611Fault last_fault() const { return last_fault_; }
  // Measuring: the PROM passed its CRC and the driver is not starting over. A fault while
  // measuring (an ADC read of 0, a NACK) keeps it healthy: the reading is discarded, the last one
  // held, and the same conversion made again; kMs5611FaultsBeforeRestart in a row end it.
  bool healthy() const { return state_ == Ms5611State::measuring; }
  uint32_t bus_busy() const { return bus_busy_; }        // begin() refused: the bus was in use
  uint64_t bus_time_ns() const { return bus_time_ns_; }  // every transfer begun, at 400 kHz
  uint32_t resets() const { return resets_; }            // reset commands begun

 private:
  enum class Phase : uint8_t { reset, prom, command, converting };

  bool next_transfer(uint32_t now_us, I2cTransfer& transfer) const;
  void begun();
  void finished(I2cResult result, const I2cReply& reply, uint32_t now_us);
  void completed(const I2cReply& reply, uint32_t now_us);
  void fault(Ms5611Fault kind, uint32_t now_us);
  void wait(Phase phase, uint32_t now_us, uint32_t wait_us);
  void start_over(Ms5611State state, uint32_t now_us);
  void converted(uint32_t value, uint32_t now_us);

  Ms5611Config config_;
  uint32_t conversion_us_;
  Ms5611State state_ = Ms5611State::starting;
  Phase phase_ = Phase::reset;
  bool on_wire_ = false;
  uint32_t since_us_ = 0;  // the phase's next transfer is due wait_us_ after since_us_
  uint32_t wait_us_ = 0;
  uint8_t prom_word_ = 0;
  Ms5611Prom prom_;
  bool d2_next_ = true;  // the next conversion is a temperature
  bool have_d2_ = false;
  uint32_t d2_ = 0;
  uint8_t pressures_since_d2_ = 0;
  uint32_t command_done_us_ = 0;
  uint8_t faults_in_a_row_ = 0;
  Ms5611Reading reading_;
  uint32_t readings_ = 0;
  uint32_t taken_ = 0;
  uint32_t reading_time_us_ = 0;
  uint32_t faults_[static_cast<size_t>(Ms5611Fault::count_)] = {};
  Ms5611Fault last_fault_ = Ms5611Fault::count_;
  uint32_t bus_busy_ = 0;
  uint64_t bus_time_ns_ = 0;
  uint32_t resets_ = 0;
};

}  // namespace drivers
