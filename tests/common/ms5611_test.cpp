// The MS5611 barometer (common/drivers/ms5611.hpp): the datasheet's worked example, AN520's CRC,
// the second-order compensation against the datasheet's formula in double precision, and the
// driver on a bus with a chip model that answers as the datasheet says the chip does.
//
// Facts: the MS5611-01BA03 datasheet (MEAS / TE Connectivity): the worked example of its
// "Pressure and temperature calculation" figure, the conversion times, the commands. A PROM with a
// known CRC and two second-order results from Betaflight's unit test
// src/test/unit/baro_ms5611_unittest.cc (github.com/betaflight/betaflight, also in Cleanflight),
// quoted as data: the PROM 0x3132 0x3334 ... 0x4344 0x450B passes, 0x...4500 does not; with the
// worked example's PROM and D1, D2 = 8069150 gives 205 (2.05 C) and 96512 Pa, D2 = 7369150 gives
// -2710 and 90613 Pa.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <deque>
#include <string>
#include <vector>

#include <common/drivers/ms5611.hpp>

namespace {

using drivers::I2cReply;
using drivers::I2cResult;
using drivers::I2cTransfer;
using drivers::Ms5611;
using drivers::Ms5611Config;
using drivers::Ms5611Fault;
using drivers::Ms5611Osr;
using drivers::Ms5611Prom;
using drivers::Ms5611Reading;
using drivers::Ms5611State;

// The worked example (datasheet, "Pressure and temperature calculation"), word 0 and word 7 ours.
constexpr uint16_t kC[7] = {0, 40127, 36924, 23317, 23282, 33464, 28312};
constexpr uint32_t kD1 = 9085466;
constexpr uint32_t kD2 = 8569150;

constexpr Ms5611Prom example_prom() {
  Ms5611Prom p{};
  for (int i = 1; i <= 6; ++i) p.word[i] = kC[i];
  p.word[0] = 0x0A5C;  // a factory word of our choosing
  p.word[7] = 0x1230;  // serial bits of our choosing; the CRC nibble written next
  return drivers::ms5611_prom_with_crc(p);
}

TEST(Ms5611, TheDatasheetsWorkedExample) {
  const Ms5611Reading r = drivers::compensate(example_prom(), kD1, kD2);
  EXPECT_EQ(r.dt, 2366);
  EXPECT_EQ(r.temp_centi_c, 2007);  // 20.07 C
  EXPECT_EQ(r.off, 2420281617);
  EXPECT_EQ(r.sens, 1315097036);
  EXPECT_EQ(r.pressure_pa, 100009);  // 1000.09 mbar
  // At 20.07 C there is no second-order term.
  EXPECT_EQ(r.t2, 0);
  EXPECT_EQ(r.off2, 0);
  EXPECT_EQ(r.sens2, 0);
  EXPECT_TRUE(r.in_range);
}

TEST(Ms5611, PrintsTheWorkedExampleAsOneJsonLine) {
  const Ms5611Reading r = drivers::compensate(example_prom(), kD1, kD2);
  std::printf(
      "MS5611 worked example: C1..C6 = %u %u %u %u %u %u, D1 = %u, D2 = %u -> dT %d, TEMP %d (%.2f C), "
      "OFF %lld, SENS %lld, P %d Pa (%.2f mbar)\n",
      unsigned{kC[1]}, unsigned{kC[2]}, unsigned{kC[3]}, unsigned{kC[4]}, unsigned{kC[5]}, unsigned{kC[6]}, kD1, kD2,
      r.dt, r.temp_centi_c, r.temp_centi_c / 100.0, static_cast<long long>(r.off), static_cast<long long>(r.sens),
      r.pressure_pa, r.pressure_pa / 100.0);
  std::printf(
      "{\"ms5611_example\": {\"dT\": %d, \"temp_centi_c\": %d, \"off\": %lld, \"sens\": %lld, \"pressure_pa\": %d}}\n",
      r.dt, r.temp_centi_c, static_cast<long long>(r.off), static_cast<long long>(r.sens), r.pressure_pa);
  std::fflush(stdout);
  RecordProperty("dT", r.dt);
  RecordProperty("temp_centi_c", r.temp_centi_c);
  RecordProperty("off", std::to_string(r.off));
  RecordProperty("sens", std::to_string(r.sens));
  RecordProperty("pressure_pa", r.pressure_pa);
  EXPECT_EQ(r.pressure_pa, 100009);
}

// AN520's CRC-4 on Betaflight's known PROM: its nibble is 0xB, and the same words with the nibble
// 0 fail. Every single bit flipped fails the check, but bits 7..4 of word 7, which AN520 reads as
// 0 (they carry no CRC protection: a fact of the procedure, not of our code).
TEST(Ms5611, Crc4OfAKnownProm) {
  Ms5611Prom known{{0x3132, 0x3334, 0x3536, 0x3738, 0x3940, 0x4142, 0x4344, 0x450B}};
  EXPECT_EQ(drivers::ms5611_crc4(known.word), 0xB);
  EXPECT_TRUE(drivers::ms5611_prom_valid(known));
  Ms5611Prom nibble_zero = known;
  nibble_zero.word[7] = 0x4500;
  EXPECT_FALSE(drivers::ms5611_prom_valid(nibble_zero));
  EXPECT_EQ(drivers::ms5611_prom_with_crc(nibble_zero).word[7], 0x450B);

  for (const Ms5611Prom& good : {known, example_prom()}) {
    ASSERT_TRUE(drivers::ms5611_prom_valid(good));
    int caught = 0, uncovered = 0;
    for (int word = 0; word < 8; ++word) {
      for (int bit = 0; bit < 16; ++bit) {
        Ms5611Prom flipped = good;
        flipped.word[word] = static_cast<uint16_t>(flipped.word[word] ^ (1u << bit));
        const bool not_covered = word == 7 && bit >= 4 && bit <= 7;
        EXPECT_EQ(drivers::ms5611_prom_valid(flipped), not_covered) << "word " << word << " bit " << bit;
        (drivers::ms5611_prom_valid(flipped) ? uncovered : caught) += 1;
      }
    }
    EXPECT_EQ(caught, 124);
    EXPECT_EQ(uncovered, 4);
  }
}

// A bus that reads zeros passes the CRC (the remainder of nothing is 0): refused all the same.
// All ones fails the CRC.
TEST(Ms5611, APromOfZerosOrOnesIsRefused) {
  Ms5611Prom zeros{};
  EXPECT_EQ(drivers::ms5611_crc4(zeros.word), 0);
  EXPECT_FALSE(drivers::ms5611_prom_valid(zeros));
  Ms5611Prom ones{{0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF}};
  EXPECT_FALSE(drivers::ms5611_prom_valid(ones));
}

// The datasheet's formulas in double precision, no rounding anywhere: the reference the integer
// compensation is held to.
struct Reference {
  double temp, off, sens, p, t2, off2, sens2;
};

Reference datasheet_in_double(double d1, double d2) {
  const double dt = d2 - kC[5] * 256.0;
  double temp = 2000 + dt * kC[6] / std::ldexp(1.0, 23);
  double off = kC[2] * std::ldexp(1.0, 16) + kC[4] * dt / 128.0;
  double sens = kC[1] * std::ldexp(1.0, 15) + kC[3] * dt / 256.0;
  double t2 = 0, off2 = 0, sens2 = 0;
  if (temp < 2000) {
    t2 = dt * dt / std::ldexp(1.0, 31);
    off2 = 5 * (temp - 2000) * (temp - 2000) / 2;
    sens2 = 5 * (temp - 2000) * (temp - 2000) / 4;
    if (temp < -1500) {
      off2 += 7 * (temp + 1500) * (temp + 1500);
      sens2 += 11 * (temp + 1500) * (temp + 1500) / 2;
    }
  }
  temp -= t2;
  off -= off2;
  sens -= sens2;
  const double p = (d1 * sens / std::ldexp(1.0, 21) - off) / std::ldexp(1.0, 15);
  return {temp, off, sens, p, t2, off2, sens2};
}

// D2 for a first-order temperature with the example's C5 and C6.
uint32_t d2_at(double temp_c) {
  return static_cast<uint32_t>(std::lround(kC[5] * 256.0 + (temp_c * 100 - 2000) * std::ldexp(1.0, 23) / kC[6]));
}

// 10 C: the first branch of the second order; -20 C: both. Each figure within the roundings of
// the integer arithmetic (a floor of each term): TEMP within 1 count (0.01 C), P within 2 Pa.
TEST(Ms5611, SecondOrderAt10CAndMinus20CIsTheDatasheetsFormula) {
  for (const double temp_c : {10.0, -20.0}) {
    for (const uint32_t d1 : {kD1, 7000000u, 10000000u}) {
      const uint32_t d2 = d2_at(temp_c);
      const Ms5611Reading r = drivers::compensate(example_prom(), d1, d2);
      const Reference ref = datasheet_in_double(d1, d2);
      SCOPED_TRACE(testing::Message() << temp_c << " C, D1 " << d1 << ": TEMP " << r.temp_centi_c << " ref " << ref.temp
                                      << ", P " << r.pressure_pa << " ref " << ref.p);
      EXPECT_GT(r.t2, 0);
      EXPECT_GT(r.off2, 0);
      EXPECT_GT(r.sens2, 0);
      EXPECT_NEAR(r.temp_centi_c, ref.temp, 1.0);
      EXPECT_NEAR(static_cast<double>(r.t2), ref.t2, 1.0);
      // OFF2 and SENS2 come from the integer (first-order, floored) TEMP: within one count of it.
      const double dtemp = std::fabs(ref.temp + ref.t2 - 2000) * 2 + 1;
      EXPECT_NEAR(static_cast<double>(r.off2), ref.off2, 5 * dtemp / 2 + (temp_c < -15 ? 7 * dtemp : 0) + 1);
      EXPECT_NEAR(static_cast<double>(r.pressure_pa), ref.p, 2.0);
      EXPECT_TRUE(r.in_range);
    }
  }
  // And where it is: 10 C reads 9.9x C after the second order (T2 = dT^2 / 2^31 = 40 counts).
  const Ms5611Reading at10 = drivers::compensate(example_prom(), kD1, d2_at(10.0));
  EXPECT_EQ(at10.temp_centi_c, drivers::ms5611_first_order_temp(example_prom(), d2_at(10.0)) - at10.t2);
  EXPECT_EQ(at10.t2, 40);
}

// Betaflight's figures for the same PROM and D1 at two colder D2: the same integers (it floors too).
TEST(Ms5611, BetaflightsSecondOrderFigures) {
  const Ms5611Reading cool = drivers::compensate(example_prom(), kD1, 8069150);
  EXPECT_EQ(cool.temp_centi_c, 205);
  EXPECT_EQ(cool.pressure_pa, 96512);
  const Ms5611Reading cold = drivers::compensate(example_prom(), kD1, 7369150);
  EXPECT_EQ(cold.temp_centi_c, -2710);
  EXPECT_EQ(cold.pressure_pa, 90613);
}

// Values that cannot be: a read of 0, more than 24 bits, a temperature or pressure out of range.
TEST(Ms5611, ValuesOutOfTheDatasheetsRangesAreFlagged) {
  const Ms5611Prom prom = example_prom();
  EXPECT_FALSE(drivers::compensate(prom, 0, kD2).in_range);
  EXPECT_FALSE(drivers::compensate(prom, kD1, 0).in_range);
  EXPECT_FALSE(drivers::compensate(prom, 1u << 24, kD2).in_range);
  EXPECT_FALSE(drivers::compensate(prom, kD1, 1u << 24).in_range);
  EXPECT_EQ(drivers::compensate(prom, kD1, 1u << 24).pressure_pa, 0);  // nothing computed
  EXPECT_FALSE(drivers::compensate(prom, 1, kD2).in_range);            // P far below 10 mbar
  EXPECT_FALSE(drivers::compensate(prom, kD1, d2_at(90)).in_range);    // 90 C
  EXPECT_FALSE(drivers::compensate(prom, kD1, d2_at(-45)).in_range);   // -45 C
  EXPECT_TRUE(drivers::compensate(prom, kD1, d2_at(80)).in_range);
  EXPECT_TRUE(drivers::compensate(prom, kD1, d2_at(-25)).in_range);
  // -35 C first order is -47 C after the second order with this PROM: out of range.
  EXPECT_FALSE(drivers::compensate(prom, kD1, d2_at(-35)).in_range);
  // The extremes of 24 bits and of the PROM compute without overflow (UBSan watches) and are no
  // reading.
  const Ms5611Prom extreme{{0, 0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF, 0xFFFF, 0}};
  for (const Ms5611Prom& p : {extreme, Ms5611Prom{}}) {
    for (uint32_t d1 : {1u, drivers::kMs5611AdcMax}) {
      for (uint32_t d2 : {1u, drivers::kMs5611AdcMax}) EXPECT_FALSE(drivers::compensate(p, d1, d2).in_range);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The driver, on a bus with a chip model. The bus runs at 400 kHz: a transfer ends its bits after
// it began (i2c.hpp's count), and poll() says pending until then. The chip, as the datasheet tells:
// a reset reloads the PROM; a conversion command starts a conversion that is ready its maximum
// conversion time after the command's end (the latest the real chip could be: a stricter test); an
// ADC read gives the result once and 0 when the conversion is not ready (it then counts an early
// read); a command during a conversion spoils it.

// The datasheet's maximum conversion times, written here apart from the driver's table.
constexpr uint32_t kConversionUs[5] = {600, 1170, 2280, 4540, 9040};

struct Begun {
  uint64_t at_ns;
  uint8_t command;
  uint8_t read_count;
};

class ChipBus {
 public:
  uint8_t address = drivers::kMs5611AddressCsbLow;
  Ms5611Prom prom = example_prom();
  uint32_t d1 = kD1, d2 = kD2;
  uint64_t now_ns = 0;
  std::vector<Begun> begun;
  std::deque<I2cResult> injected;  // results for the next transfers to finish, the chip unaware
  int zero_adc_reads = 0;          // the next ADC reads answer 0 although a conversion is ready
  bool refuse_begin = false;       // another master holds the bus
  int early_reads = 0;             // ADC reads before the conversion was ready
  int spoilt_conversions = 0;      // commands during a conversion
  int reads_during_reset = 0;      // PROM reads before the reload ended

  bool begin(const I2cTransfer& t) {
    if (on_wire_ || refuse_begin) return false;
    on_wire_ = true;
    transfer_ = t;
    begun_ns_ = now_ns;
    end_ns_ = now_ns + drivers::transfer_time_ns(t, 400000);
    begun.push_back({now_ns, t.write[0], t.read_count});
    return true;
  }

  I2cResult poll(I2cReply& reply) {
    if (!on_wire_) return I2cResult::idle;
    if (now_ns < end_ns_) return I2cResult::pending;
    on_wire_ = false;
    if (!injected.empty()) {
      const I2cResult r = injected.front();
      injected.pop_front();
      return r;
    }
    if (transfer_.address != address) return I2cResult::address_nack;
    return answer(reply);
  }

  uint64_t transfers_with(uint8_t command) const {
    uint64_t n = 0;
    for (const Begun& b : begun) n += b.command == command ? 1 : 0;
    return n;
  }

 private:
  I2cResult answer(I2cReply& reply) {
    const uint8_t c = transfer_.write[0];
    if (transfer_.read_count == 0) {
      if (c == drivers::kMs5611Reset) {
        converting_ = false;
        ready_ns_ = 0;
        reloaded_ns_ = end_ns_ + drivers::kMs5611ResetTimeUs * 1000ull;
        return I2cResult::ok;
      }
      const bool is_d1 = c >= 0x40 && c <= 0x48 && c % 2 == 0;
      const bool is_d2 = c >= 0x50 && c <= 0x58 && c % 2 == 0;
      if (!is_d1 && !is_d2) return I2cResult::data_nack;
      if (converting_ && now_ns < ready_ns_) ++spoilt_conversions;
      converting_ = true;
      result_ = is_d1 ? d1 : d2;
      ready_ns_ = end_ns_ + kConversionUs[(c & 0x0F) / 2] * 1000ull;
      return I2cResult::ok;
    }
    if (c == drivers::kMs5611AdcRead && transfer_.read_count == 3) {
      uint32_t value = 0;
      if (converting_ && begun_ns_ >= ready_ns_ && zero_adc_reads == 0) value = result_;
      if (converting_ && begun_ns_ < ready_ns_) ++early_reads;
      if (zero_adc_reads > 0) --zero_adc_reads;
      converting_ = false;
      reply.count = 3;
      reply.data[0] = static_cast<uint8_t>(value >> 16);
      reply.data[1] = static_cast<uint8_t>(value >> 8);
      reply.data[2] = static_cast<uint8_t>(value);
      return I2cResult::ok;
    }
    if (c >= 0xA0 && c <= 0xAE && c % 2 == 0 && transfer_.read_count == 2) {
      if (begun_ns_ < reloaded_ns_) ++reads_during_reset;
      const uint16_t w = prom.word[(c - 0xA0) / 2];
      reply.count = 2;
      reply.data[0] = static_cast<uint8_t>(w >> 8);
      reply.data[1] = static_cast<uint8_t>(w);
      return I2cResult::ok;
    }
    return I2cResult::data_nack;
  }

  bool on_wire_ = false;
  I2cTransfer transfer_;
  uint64_t begun_ns_ = 0, end_ns_ = 0;
  bool converting_ = false;
  uint64_t ready_ns_ = 0, reloaded_ns_ = 0;
  uint32_t result_ = 0;
};

// Steps the driver every `step_us` from the bus' time until `end_us`.
void run(Ms5611& baro, ChipBus& bus, uint64_t end_us, uint32_t step_us = 1) {
  for (uint64_t t = bus.now_ns / 1000; t < end_us; t += step_us) {
    bus.now_ns = t * 1000;
    baro.step(bus, static_cast<uint32_t>(t));
  }
  bus.now_ns = end_us * 1000;
}

// Runs until the driver has `n` readings (or `limit_us` passes).
void run_to_readings(Ms5611& baro, ChipBus& bus, uint32_t n, uint64_t limit_us = 5000000, uint32_t step_us = 1) {
  for (uint64_t t = bus.now_ns / 1000; t < limit_us && baro.readings() < n; t += step_us) {
    bus.now_ns = t * 1000;
    baro.step(bus, static_cast<uint32_t>(t));
  }
}

uint64_t ceil_us(uint64_t ns) { return (ns + 999) / 1000; }

// The whole conversation from power-up, stepped every microsecond at OSR 4096, one D2 per two D1:
// every transfer at the time it must begin. Bit counts at 400 kHz (2.5 us a bit): a command 20
// bits (50 us), a PROM word 48 (120 us), an ADC read 57 (142.5 us); the reset's 2.8 ms; the
// conversion's 9.04 ms, counted from the command's end as the driver sees it.
TEST(Ms5611Driver, TheExactSequenceOfTransfers) {
  ChipBus bus;
  Ms5611 baro({drivers::kMs5611AddressCsbLow, Ms5611Osr::osr4096, 2});
  run_to_readings(baro, bus, 4);
  ASSERT_EQ(baro.readings(), 4u);

  std::vector<Begun> want;
  uint64_t t_ns = 0;
  auto expect = [&](uint8_t command, uint8_t read_count, uint64_t bits) {
    want.push_back({t_ns, command, read_count});
    t_ns = ceil_us(t_ns + bits * 2500) * 1000;  // the step that sees it end
  };
  expect(0x1E, 0, 20);
  t_ns += 2800000;
  for (uint8_t w = 0; w < 8; ++w) expect(static_cast<uint8_t>(0xA0 + 2 * w), 2, 48);
  const uint8_t conversions[] = {0x58, 0x48, 0x48, 0x58, 0x48, 0x48};
  for (const uint8_t c : conversions) {
    expect(c, 0, 20);
    t_ns += 9040000;
    expect(0x00, 3, 57);
  }
  const size_t last_d1 = want.size() - 2;
  expect(0x58, 0, 20);  // begun by the step that made the fourth reading
  ASSERT_EQ(bus.begun.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(bus.begun[i].at_ns, want[i].at_ns) << "transfer " << i;
    EXPECT_EQ(bus.begun[i].command, want[i].command) << "transfer " << i;
    EXPECT_EQ(bus.begun[i].read_count, want[i].read_count) << "transfer " << i;
  }
  EXPECT_EQ(bus.early_reads, 0);
  EXPECT_EQ(bus.spoilt_conversions, 0);
  EXPECT_EQ(bus.reads_during_reset, 0);
  EXPECT_EQ(baro.total_faults(), 0u);
  EXPECT_EQ(baro.state(), Ms5611State::measuring);
  EXPECT_EQ(baro.reading().pressure_pa, 100009);
  EXPECT_EQ(baro.reading().temp_centi_c, 2007);
  // The last reading's pressure conversion: its command seen complete 50 us after it began.
  EXPECT_EQ(uint64_t{baro.reading_time_us()} * 1000, want[last_d1].at_ns + 50000);
  // Bus time at 400 kHz: reset 50 us, 8 PROM words 960 us, 6 conversions of 192.5 us, the
  // seventh's command 50 us.
  EXPECT_EQ(baro.bus_time_ns(), 50000u + 8 * 120000u + 6 * (50000u + 142500u) + 50000u);
  EXPECT_EQ(drivers::kMs5611CommandNs, 50000u);
  EXPECT_EQ(drivers::kMs5611PromWordNs, 120000u);
  EXPECT_EQ(drivers::kMs5611AdcReadNs, 142500u);
}

// For every OSR: the first ADC read begins exactly the datasheet's maximum conversion time after
// the command's end, never sooner (the chip model answers 0 to a read 1 us early: shortening a
// row of kMs5611Osr by 1 us fails here), and the command bytes are the datasheet's.
TEST(Ms5611Driver, NoAdcReadBeforeTheConversionTime) {
  for (uint8_t k = 0; k < 5; ++k) {
    const auto osr = static_cast<Ms5611Osr>(k);
    SCOPED_TRACE(testing::Message() << "OSR " << (256 << k));
    ChipBus bus;
    Ms5611 baro({drivers::kMs5611AddressCsbLow, osr, 1});
    run_to_readings(baro, bus, 3);
    ASSERT_EQ(baro.readings(), 3u);
    EXPECT_EQ(bus.early_reads, 0);
    EXPECT_EQ(baro.total_faults(), 0u);
    int reads = 0;
    for (size_t i = 9; i < bus.begun.size(); ++i) {
      if (bus.begun[i].command != drivers::kMs5611AdcRead) continue;
      ++reads;
      const Begun& command = bus.begun[i - 1];
      EXPECT_EQ(command.command, ((reads % 2 == 1) ? 0x50 : 0x40) + 2 * k);
      EXPECT_EQ(bus.begun[i].at_ns, command.at_ns + 50000 + kConversionUs[k] * 1000ull) << "read " << reads;
    }
    EXPECT_EQ(reads, 6);
  }
}

// The readings a second at a 1 kHz tick, the driver's rates in its header: a conversion takes 12
// ticks at OSR 4096 (the command's end seen a tick later, 9.04 ms as 10 ticks, the read's end a
// tick later).
TEST(Ms5611Driver, ReadingsASecondAtA1kHzTick) {
  for (const int per_temperature : {1, 4}) {
    ChipBus bus;
    Ms5611 baro({drivers::kMs5611AddressCsbLow, Ms5611Osr::osr4096, static_cast<uint8_t>(per_temperature)});
    run(baro, bus, 1000000, 1000);  // the start-up, then one second
    const uint32_t before = baro.readings();
    run(baro, bus, 2000000, 1000);
    const uint32_t per_second = baro.readings() - before;
    std::printf("MS5611 at OSR 4096, %d pressures per temperature, 1 kHz tick: %u readings a second\n", per_temperature,
                per_second);
    EXPECT_NEAR(per_second, per_temperature == 1 ? 1000.0 / 24 : 4 * 1000.0 / 60, 1.0);
    EXPECT_EQ(baro.total_faults(), 0u);
    EXPECT_EQ(bus.early_reads, 0);
  }
}

// No chip (or the wrong CSB): the reset's address is not acknowledged. Counted; a reset again
// each kMs5611RestartDelayUs, nothing else on the bus.
TEST(Ms5611Driver, NoChipIsAnAddressNackAndAResetEverySecond) {
  ChipBus bus;
  bus.address = drivers::kMs5611AddressCsbHigh;
  Ms5611 baro;
  run(baro, bus, 2500000, 1000);
  EXPECT_EQ(baro.state(), Ms5611State::restarting);
  EXPECT_EQ(baro.faults(Ms5611Fault::address_nack), 3u);
  EXPECT_EQ(baro.total_faults(), 3u);
  EXPECT_EQ(baro.resets(), 3u);
  ASSERT_EQ(bus.begun.size(), 3u);
  EXPECT_EQ(bus.begun[1].at_ns, 1001000000u);  // the NACK seen at 1 ms, then 1 s
  EXPECT_EQ(bus.transfers_with(drivers::kMs5611Reset), 3u);
  EXPECT_EQ(baro.readings(), 0u);
}

// A NACK while measuring: counted, a conversion time let pass, the command again; readings go on.
TEST(Ms5611Driver, ANackWhileMeasuringIsCountedAndTheConversionRepeated) {
  ChipBus bus;
  Ms5611 baro;
  run_to_readings(baro, bus, 2);
  // The step that made the reading began the next command: it will not be acknowledged.
  ASSERT_EQ(bus.begun.back().read_count, 0);
  const uint8_t command = bus.begun.back().command;
  const size_t at = bus.begun.size();
  bus.injected.push_back(I2cResult::data_nack);
  run_to_readings(baro, bus, 4);
  EXPECT_EQ(baro.readings(), 4u);
  EXPECT_EQ(baro.faults(Ms5611Fault::data_nack), 1u);
  EXPECT_EQ(baro.total_faults(), 1u);
  EXPECT_EQ(baro.state(), Ms5611State::measuring);
  ASSERT_GT(bus.begun.size(), at);
  EXPECT_EQ(bus.begun[at].command, command);                                  // the same conversion again ...
  EXPECT_EQ(bus.begun[at].at_ns, bus.begun[at - 1].at_ns + 50000 + 9040000);  // ... a conversion time later
  EXPECT_EQ(bus.early_reads, 0);
  EXPECT_EQ(bus.spoilt_conversions, 0);
}

// A PROM with one bit wrong: prom_bad, no conversion begun, a reset again a second after; a good
// PROM then reads and readings come.
TEST(Ms5611Driver, ABadCrcIsAClearStateAndTheResetIsRetried) {
  ChipBus bus;
  bus.prom.word[3] ^= 0x0100;
  Ms5611 baro;
  run(baro, bus, 500000);
  EXPECT_EQ(baro.state(), Ms5611State::prom_bad);
  EXPECT_EQ(baro.faults(Ms5611Fault::prom_crc), 1u);
  EXPECT_EQ(baro.total_faults(), 1u);
  EXPECT_EQ(bus.begun.size(), 9u);  // the reset and 8 PROM words, nothing after
  const uint64_t prom_read_ns = bus.begun.back().at_ns + 120000;
  run(baro, bus, 1500000);
  EXPECT_EQ(baro.resets(), 2u);
  ASSERT_EQ(bus.begun.size(), 18u);
  EXPECT_EQ(bus.begun[9].command, drivers::kMs5611Reset);
  EXPECT_EQ(bus.begun[9].at_ns, prom_read_ns + 1000000000u);
  EXPECT_EQ(baro.readings(), 0u);
  EXPECT_EQ(baro.faults(Ms5611Fault::prom_crc), 2u);

  bus.prom = example_prom();
  run_to_readings(baro, bus, 1);
  EXPECT_EQ(baro.state(), Ms5611State::measuring);
  EXPECT_EQ(baro.readings(), 1u);
  EXPECT_EQ(baro.reading().pressure_pa, 100009);
}

// An ADC read of 0 (the chip had no conversion to give): counted, no reading made of it.
TEST(Ms5611Driver, AZeroFromTheAdcIsCountedAndNoReading) {
  ChipBus bus;
  Ms5611 baro;
  run_to_readings(baro, bus, 1);
  bus.zero_adc_reads = 1;
  run_to_readings(baro, bus, 3);
  EXPECT_EQ(baro.faults(Ms5611Fault::adc_zero), 1u);
  EXPECT_EQ(baro.total_faults(), 1u);
  EXPECT_EQ(baro.reading().pressure_pa, 100009);
  EXPECT_EQ(bus.early_reads, 0);
}

// A stuck bus: each transfer fails; after kMs5611FaultsBeforeRestart in a row the driver starts
// over (restarting, a reset a second later) and measures again once the bus is free.
TEST(Ms5611Driver, FaultsInARowStartOver) {
  ChipBus bus;
  Ms5611 baro;
  run_to_readings(baro, bus, 1);
  for (int i = 0; i < drivers::kMs5611FaultsBeforeRestart; ++i) bus.injected.push_back(I2cResult::bus_stuck);
  run(baro, bus, bus.now_ns / 1000 + 200000);
  EXPECT_EQ(baro.faults(Ms5611Fault::bus_stuck), uint32_t{drivers::kMs5611FaultsBeforeRestart});
  EXPECT_EQ(baro.state(), Ms5611State::restarting);
  EXPECT_EQ(baro.resets(), 1u);
  run_to_readings(baro, bus, 2);
  EXPECT_EQ(baro.resets(), 2u);
  EXPECT_EQ(baro.state(), Ms5611State::measuring);
  EXPECT_EQ(baro.readings(), 2u);
  EXPECT_EQ(bus.spoilt_conversions, 0);
}

// A pressure that cannot be (a D1 of 1): counted, never a reading; the PROM read again after
// kMs5611FaultsBeforeRestart of them.
TEST(Ms5611Driver, AValueOutOfRangeIsCountedAndNeverAReading) {
  ChipBus bus;
  bus.d1 = 1;
  Ms5611 baro;
  run(baro, bus, 300000);
  EXPECT_EQ(baro.readings(), 0u);
  EXPECT_EQ(baro.faults(Ms5611Fault::out_of_range), uint32_t{drivers::kMs5611FaultsBeforeRestart});
  EXPECT_EQ(baro.state(), Ms5611State::restarting);
  bus.d1 = kD1;
  run_to_readings(baro, bus, 1);
  EXPECT_EQ(baro.reading().pressure_pa, 100009);
}

// A short reply and a forgotten transfer (poll() idle) are bad replies.
TEST(Ms5611Driver, ABusThatAnswersNonsenseIsABadReply) {
  struct ShortBus {
    bool on_wire = false;
    bool forget = false;
    bool begin(const I2cTransfer&) {
      if (on_wire) return false;
      on_wire = true;
      return true;
    }
    I2cResult poll(I2cReply& reply) {
      if (!on_wire) return I2cResult::idle;
      on_wire = false;
      reply.count = 1;
      return forget ? I2cResult::idle : I2cResult::ok;
    }
  } bus;
  Ms5611 baro;
  for (uint32_t t = 0; t < 10000; ++t) baro.step(bus, t);  // reset ok, PROM word 0 one byte short
  EXPECT_EQ(baro.faults(Ms5611Fault::bad_reply), 1u);
  EXPECT_EQ(baro.state(), Ms5611State::restarting);
  bus.forget = true;
  for (uint32_t t = 10000; t < 1200000; t += 100) baro.step(bus, t);
  EXPECT_EQ(baro.faults(Ms5611Fault::bad_reply), 2u);
}

// Another master on the bus: begin() refused is no fault; the transfer goes when the bus is free.
TEST(Ms5611Driver, ABusInUseIsWaitedFor) {
  ChipBus bus;
  bus.refuse_begin = true;
  Ms5611 baro;
  run(baro, bus, 100);
  EXPECT_EQ(baro.bus_busy(), 100u);
  EXPECT_TRUE(bus.begun.empty());
  bus.refuse_begin = false;
  run_to_readings(baro, bus, 1);
  EXPECT_EQ(baro.total_faults(), 0u);
  EXPECT_EQ(bus.begun[0].at_ns, 100000u);
}

// The microsecond clock wraps every 71.6 minutes: the waits hold across it.
TEST(Ms5611Driver, TheClocksWrapChangesNothing) {
  ChipBus bus;
  Ms5611 baro;
  const uint64_t start = 0xFFFFFFFFull - 1000;  // the wrap falls inside the PROM's reload
  bus.now_ns = start * 1000;
  for (uint64_t t = start; baro.readings() < 3 && t < start + 200000; ++t) {
    bus.now_ns = t * 1000;
    baro.step(bus, static_cast<uint32_t>(t));
  }
  EXPECT_EQ(baro.readings(), 3u);
  EXPECT_EQ(bus.early_reads, 0);
  EXPECT_EQ(bus.reads_during_reset, 0);
  EXPECT_EQ(baro.total_faults(), 0u);
}

// On a shared bus (i2c.hpp's I2cQueue) behind another driver's 14-byte burst every millisecond
// (the MPU-6050's, 390 us at 400 kHz): a command or read waits its turn on the wire, the driver
// counts the conversion from the end it sees, and the chip is never read early.
TEST(Ms5611Driver, OnASharedBusBehindAnotherDriversBurst) {
  struct Wire {
    drivers::I2cQueue<2> queue;
    ChipBus chip;
    bool busy = false;
    uint8_t channel = 0;
    void service() {
      if (busy) {
        I2cReply reply;
        const I2cResult result = chip.poll(reply);
        if (result == I2cResult::pending) return;
        queue.finish(channel, result, reply);
        busy = false;
      }
      I2cTransfer t;
      if (queue.next(channel, t)) busy = chip.begin(t);
    }
  } wire;
  drivers::I2cChannel<drivers::I2cQueue<2>> baro_channel(wire.queue, 0);
  Ms5611 baro;
  uint32_t burst_results = 0, delayed = 0;
  for (uint64_t t = 0; t < 200000 && baro.readings() < 5; ++t) {
    wire.chip.now_ns = t * 1000;
    wire.service();
    if (t % 1000 == 0) {
      I2cReply ignored;
      if (wire.queue.poll(1, ignored) != I2cResult::pending) ++burst_results;
      EXPECT_TRUE(wire.queue.begin(1, drivers::read_registers(0x68, 0x3B, 14)));
    }
    const uint64_t bus_before = baro.bus_time_ns();
    baro.step(baro_channel, static_cast<uint32_t>(t));
    wire.service();
    // The driver began a transfer: on the wire at once, or queued behind the burst?
    if (baro.bus_time_ns() != bus_before) {
      const Begun& last = wire.chip.begun.back();
      if (last.at_ns != t * 1000 || last.read_count == 14) ++delayed;
    }
  }
  EXPECT_EQ(baro.readings(), 5u);
  EXPECT_EQ(baro.reading().pressure_pa, 100009);
  EXPECT_EQ(baro.total_faults(), 0u);
  EXPECT_EQ(wire.chip.early_reads, 0);
  EXPECT_EQ(wire.chip.spoilt_conversions, 0);
  EXPECT_EQ(wire.chip.reads_during_reset, 0);
  EXPECT_GT(burst_results, 40u);
  EXPECT_GT(delayed, 0u);
}

// take() hands each reading once.
TEST(Ms5611Driver, TakeHandsEachReadingOnce) {
  ChipBus bus;
  Ms5611 baro;
  Ms5611Reading r;
  EXPECT_FALSE(baro.take(r));
  run_to_readings(baro, bus, 1);
  EXPECT_TRUE(baro.take(r));
  EXPECT_EQ(r.pressure_pa, 100009);
  EXPECT_FALSE(baro.take(r));
}

TEST(Ms5611Driver, FaultNamesAreTheRows) {
  EXPECT_STREQ(drivers::kMs5611FaultNames[static_cast<size_t>(Ms5611Fault::adc_zero)], "adc_zero");
  EXPECT_STREQ(drivers::kMs5611FaultNames[static_cast<size_t>(Ms5611Fault::prom_crc)], "prom_crc");
  EXPECT_STREQ(drivers::kMs5611FaultNames[static_cast<size_t>(Ms5611Fault::out_of_range)], "out_of_range");
}

}  // namespace
