// Fuzz target: the MS5611 driver (common/drivers/ms5611.hpp) on a bus whose every answer comes
// from the input: begin() taken or refused, how long a transfer stays pending, its result (ok,
// NACKs, stuck, forgotten), how many bytes come back and which: either a chip's honest answer (the
// datasheet's example PROM, D1 and D2 near the example's) or bytes from the input. The time between
// steps comes from the input too, starting near the wrap of the microsecond clock. Checks, beyond
// ASan and UBSan:
//   - the driver begins a transfer only when none of its own is on the wire, polls only then, and
//     speaks to its own address;
//   - the first PROM read comes the reset time after the reset was seen complete;
//   - a conversion command only while measuring, with the configured OSR, and never sooner than a
//     conversion time after the previous one ended (a conversion is never spoilt);
//   - an ADC read only after a conversion command ended ok, and a conversion time after it;
//   - every reading is in the datasheet's ranges, from a PROM that passes its check, comes only
//     while measuring and is taken once;
//   - fault counts never go down, and their total is their sum.
#include <stddef.h>
#include <stdint.h>

#include <common/drivers/ms5611.hpp>

#include "fuzz_checks.hpp"

namespace {

using drivers::I2cReply;
using drivers::I2cResult;
using drivers::I2cTransfer;
using drivers::Ms5611;
using drivers::Ms5611Fault;
using drivers::Ms5611State;
using fuzz::require;

struct Input {
  const uint8_t* data;
  size_t size;
  size_t pos = 0;
  bool done() const { return pos >= size; }
  uint8_t byte() { return pos < size ? data[pos++] : 0; }
};

constexpr drivers::Ms5611Prom kExampleProm = drivers::ms5611_prom_with_crc(
    {{0x0A5C, 40127, 36924, 23317, 23282, 33464, 28312, 0x1230}});

bool is_conversion(uint8_t c) { return (c & 0xE0) == 0x40 && (c & 0x0F) <= 0x08; }

class FuzzBus {
 public:
  FuzzBus(Input& in, const Ms5611& baro, uint8_t address, uint8_t command_offset, uint32_t conversion_us)
      : in_(in), baro_(baro), address_(address), offset_(command_offset), conversion_us_(conversion_us) {}

  uint32_t now_us = 0;

  bool begin(const I2cTransfer& t) {
    require(!on_wire_);
    const uint8_t b = in_.byte();
    if ((b & 0x0F) == 0) return false;  // another master has the bus
    require(t.address == address_);
    const uint8_t c = t.write[0];
    if (c == drivers::kMs5611Reset) {
      require(t.write_count == 1 && t.read_count == 0);
      conversion_ok_ = false;
      reset_ok_ = false;
    } else if (c >= drivers::kMs5611PromRead && c < drivers::kMs5611PromRead + 16) {
      require(t.write_count == 1 && t.read_count == 2);
      if (c == drivers::kMs5611PromRead) require(reset_ok_ && now_us - reset_end_us_ >= drivers::kMs5611ResetTimeUs);
    } else if (is_conversion(c)) {
      require(t.write_count == 1 && t.read_count == 0);
      require(baro_.state() == Ms5611State::measuring);
      require((c & 0x0F) == offset_);
      if (any_conversion_) require(now_us - conversion_end_us_ >= conversion_us_);
    } else {
      require(c == drivers::kMs5611AdcRead && t.write_count == 1 && t.read_count == 3);
      require(conversion_ok_ && now_us - conversion_end_us_ >= conversion_us_);
      conversion_ok_ = false;
    }
    transfer_ = t;
    on_wire_ = true;
    pending_polls_ = (b >> 4) & 3u;
    return true;
  }

  I2cResult poll(I2cReply& reply) {
    require(on_wire_);
    if (pending_polls_ > 0) {
      --pending_polls_;
      return I2cResult::pending;
    }
    on_wire_ = false;
    // Mostly the chip's honest answer (so that runs reach the measuring), else one fault or
    // another: bytes from the input, a wrong count, a NACK, a stuck bus, a forgotten transfer.
    const uint8_t b = in_.byte();
    I2cResult result = I2cResult::ok;
    if (b >= 184 && b < 216) {
      static constexpr I2cResult kFaults[4] = {I2cResult::address_nack, I2cResult::data_nack, I2cResult::bus_stuck,
                                               I2cResult::idle};
      result = kFaults[(b - 184) / 8];
    }
    const uint8_t c = transfer_.write[0];
    if (is_conversion(c)) {
      any_conversion_ = true;
      conversion_end_us_ = now_us;
      conversion_ok_ = result == I2cResult::ok;
      d2_ = (c & 0xF0) == drivers::kMs5611ConvertD2;
    }
    if (c == drivers::kMs5611Reset && result == I2cResult::ok) {
      reset_ok_ = true;
      reset_end_us_ = now_us;
    }
    if (transfer_.read_count == 0) return result;
    reply.count = transfer_.read_count;
    if (b >= 176 && b < 184) reply.count = static_cast<uint8_t>(in_.byte() % (drivers::kI2cMaxRead + 1));
    if (b >= 160 && b < 184) {
      for (uint8_t i = 0; i < reply.count; ++i) reply.data[i] = in_.byte();
    } else {
      honest(c, reply);
    }
    return result;
  }

 private:
  // What the chip would say: its PROM, or a D1 or D2 about the worked example's (D2 within
  // +-2^20, -15..55 C: both branches of the second order; D1 within +-2^19).
  void honest(uint8_t c, I2cReply& reply) {
    if (c == drivers::kMs5611AdcRead) {
      const uint32_t base = d2_ ? 8569150u : 9085466u;
      const uint32_t value = base + (uint32_t{in_.byte()} << (d2_ ? 13 : 12)) - (d2_ ? 0x100000u : 0x80000u);
      reply.data[0] = static_cast<uint8_t>(value >> 16);
      reply.data[1] = static_cast<uint8_t>(value >> 8);
      reply.data[2] = static_cast<uint8_t>(value);
    } else {
      const uint16_t w = kExampleProm.word[(c - drivers::kMs5611PromRead) / 2 % 8];
      reply.data[0] = static_cast<uint8_t>(w >> 8);
      reply.data[1] = static_cast<uint8_t>(w);
    }
  }

  Input& in_;
  const Ms5611& baro_;
  uint8_t address_, offset_;
  uint32_t conversion_us_;
  bool on_wire_ = false;
  I2cTransfer transfer_;
  uint32_t pending_polls_ = 0;
  bool reset_ok_ = false;
  uint32_t reset_end_us_ = 0;
  bool any_conversion_ = false;
  bool conversion_ok_ = false;
  bool d2_ = false;
  uint32_t conversion_end_us_ = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Input in{data, size};
  drivers::Ms5611Config config;
  const uint8_t setup = in.byte();
  config.address = (setup & 1u) ? drivers::kMs5611AddressCsbHigh : drivers::kMs5611AddressCsbLow;
  config.osr = static_cast<drivers::Ms5611Osr>((setup >> 1) % 5);
  config.pressures_per_temperature = static_cast<uint8_t>(setup >> 4);
  const drivers::Ms5611OsrRow& row = drivers::ms5611_osr_row(config.osr);
  Ms5611 baro(config);
  FuzzBus bus(in, baro, config.address, row.command_offset, row.conversion_us);
  bus.now_us = 0xFFFFFFFFu - (uint32_t{in.byte()} << 12);  // the clock wraps early in many runs

  uint32_t faults[static_cast<size_t>(Ms5611Fault::count_)] = {};
  uint32_t readings = 0;
  // At most 3000 steps of at most 1.28 s: less than one turn of the clock (71.6 min) in a run, so a
  // difference of two times read modulo 2^32 is the time between them.
  for (int steps = 0; !in.done() && steps < 3000; ++steps) {
    const uint8_t t = in.byte();
    // Mostly short steps (a tick or less), sometimes long ones (the restart delay passes).
    bus.now_us += t < 224 ? uint32_t{t} * 50u : (uint32_t{t} - 223u) * 40000u;
    baro.step(bus, bus.now_us);
    uint32_t total = 0;
    for (size_t k = 0; k < static_cast<size_t>(Ms5611Fault::count_); ++k) {
      const uint32_t n = baro.faults(static_cast<Ms5611Fault>(k));
      require(n >= faults[k]);
      faults[k] = n;
      total += n;
    }
    require(baro.total_faults() == total);
    if (baro.readings() != readings) {
      require(baro.readings() == readings + 1);
      readings = baro.readings();
      require(baro.state() == Ms5611State::measuring);
      const drivers::Ms5611Reading& r = baro.reading();
      require(r.in_range);
      require(r.temp_centi_c >= drivers::kMs5611TempMinCentiC && r.temp_centi_c <= drivers::kMs5611TempMaxCentiC);
      require(r.pressure_pa >= drivers::kMs5611PressureMinPa && r.pressure_pa <= drivers::kMs5611PressureMaxPa);
      require(drivers::ms5611_prom_valid(baro.prom()));
      drivers::Ms5611Reading taken;
      require(baro.take(taken) && taken.pressure_pa == r.pressure_pa && !baro.take(taken));
    }
  }
  return 0;
}
