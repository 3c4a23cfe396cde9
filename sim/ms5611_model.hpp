// The MS5611 at register level: the chip a firmware driver talks to over I2C, with the plant's
// pressure and the board's temperature behind its ADC.
//
// Sources:
//   [DS]    MEAS (TE Connectivity) MS5611-01BA03 datasheet: "Commands", "Pressure and temperature
//           calculation", "Second order temperature compensation", "Conversion sequence",
//           "PROM read sequence", "Reset sequence", "Memory PROM mapping", "I2C interface".
//   [AN520] MEAS AN520, "C-code example for MS56xx, MS57xx (except analog sensor), and MS58xx
//           series pressure sensors": the PROM's 4-bit CRC.
//
// What it does, and where each behaviour comes from:
// - Address 111011Cx, C the complement of the CSB pin: 0x77 with CSB low (the GY-86), 0x76 high.
// - Five commands, one byte each [DS]: reset 0x1E; convert D1 (pressure) 0x40 + 2 osr and D2
//   (temperature) 0x50 + 2 osr, osr 0..4 for OSR 256..4096; ADC read 0x00, after which a read
//   gives the 24-bit result, most significant byte first; PROM read 0xA0 + 2 n, n 0..7, after
//   which a read gives word n, most significant byte first. Any other byte is refused (a NACK:
//   our choice, the datasheet lists no others).
// - Conversion time, the datasheet's maximum ("ADC conversion time" in "Operating range and
//   performance"): 0.60, 1.17, 2.28, 4.54, 9.04 ms for OSR 256..4096.
// - [DS] "Conversion sequence": "If the conversion is not executed before the ADC read command,
//   or the ADC read command is repeated, it will give 0 as the output result. If the ADC read
//   command is sent during conversion the result will be 0, the conversion will not stop and the
//   final result will be wrong. Conversion sequence sent during the already started conversion
//   process will yield incorrect result as well." The datasheet does not say how wrong: the model
//   gives half the right code (our choice; a driver cannot tell it by its look, as on the part).
// - Reset: the PROM is reloaded, which takes 2.8 ms (the reset sequence figures); meanwhile the
//   chip does not acknowledge its address (our reading: the datasheet says what it does, not how it
//   answers). Power-up is taken as the same reset.
// - PROM [DS] "Memory PROM mapping": word 0 factory data and setup, words 1..6 the coefficients
//   C1..C6, word 7 the serial code and, in its low 4 bits, the CRC of [AN520] (ms5611_crc4).
// - The codes: D1 and D2 are what the datasheet's compensation, first and second order, turns
//   back into the pressure and temperature the chip senses (ms5611_codes inverts it in double
//   precision). The pressure comes from the world with its noise and drift already in
//   (Barometer::sense_pa, the barometer's own model); the temperature is the board's
//   (Barometer::temperature_c). A conversion converts what the chip senses at its middle: the
//   first sense() at or after it (next_sample_s() says when), or the last one before the result
//   is read if none came.
//
// Not modelled: the temperature's own noise (0.002 to 0.012 °C RMS), the SPI interface, the
// SDA held low after a failed power-on reset ([DS] "Reset sequence": the bus' fault, the board's).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <array>
#include <optional>

#include <sim/i2c_device.hpp>

namespace sim {

using Ms5611Prom = std::array<uint16_t, 8>;

// [AN520]'s CRC-4 of the PROM: the eight words, word 7's low byte taken as 0, through the
// polynomial 0x3000 on a 16-bit remainder, the top 4 bits of which are the CRC.
uint8_t ms5611_crc4(const Ms5611Prom& prom);

// The datasheet's example coefficients (C1 40127, C2 36924, C3 23317, C4 23282, C5 33464,
// C6 28312), word 0 = 0, a serial code of 0x4B0 in word 7 and its correct CRC in the low nibble.
Ms5611Prom ms5611_example_prom();

// D1 and D2, 24-bit codes, such that the datasheet's compensation with `prom` (first and second
// order, in exact arithmetic) gives back `pressure_pa` (1 Pa = 0.01 mbar, the datasheet's P unit)
// and `temperature_c`, to within the rounding of the codes.
struct Ms5611Codes {
  uint32_t d1 = 0;
  uint32_t d2 = 0;
};
Ms5611Codes ms5611_codes(const Ms5611Prom& prom, double pressure_pa, double temperature_c);

struct Ms5611Faults {
  bool bad_prom_crc = false;  // word 7's CRC bit 0 read inverted: the PROM fails its check
  // Each conversion commanded takes this much longer than the datasheet's maximum (a part out of
  // its specification, or one too cold): a driver that reads after the datasheet's time reads
  // too early, and gets 0 ([DS] "Conversion sequence").
  double slow_conversion_s = 0;
};

class Ms5611Model final : public I2cDevice {
 public:
  static constexpr uint8_t kAddressCsbLow = 0x77;
  static constexpr uint8_t kAddressCsbHigh = 0x76;
  static constexpr uint8_t kReset = 0x1E;
  static constexpr uint8_t kConvertD1 = 0x40;  // + 2 osr
  static constexpr uint8_t kConvertD2 = 0x50;  // + 2 osr
  static constexpr uint8_t kAdcRead = 0x00;
  static constexpr uint8_t kPromRead = 0xA0;  // + 2 word
  static constexpr double kResetS = 2.8e-3;
  static constexpr std::array<double, 5> kConversionS = {0.60e-3, 1.17e-3, 2.28e-3, 4.54e-3, 9.04e-3};
  // Pressure resolution RMS per OSR, Pa ([DS] "Operating range and performance": 0.065 to 0.012 mbar).
  static constexpr std::array<double, 5> kResolutionPa = {6.5, 4.2, 2.7, 1.8, 1.2};

  explicit Ms5611Model(uint8_t address = kAddressCsbLow, const Ms5611Prom& prom = ms5611_example_prom(),
                       double power_on_s = 0);

  uint8_t address() const override { return address_; }
  I2cAck write(const uint8_t* bytes, size_t n, double t_s) override;
  I2cAck read(uint8_t* out, size_t n, double t_s) override;

  // What the chip senses at `t_s`: the pressure (Pa, noise and drift included) and its temperature, °C.
  void sense(double t_s, double pressure_pa, double temperature_c);
  // The instant the conversion under way wants to sense (its middle), until it has.
  std::optional<double> next_sample_s() const;
  // The noise of the conversion under way over the barometer's (its OSR's resolution over OSR
  // 4096's): what Barometer::sense_pa's noise_scale should be for it; 1 with none under way.
  double noise_scale() const;

  void set_faults(const Ms5611Faults& faults) { faults_ = faults; }

  bool answers(double t_s) const { return t_s >= ready_s_; }
  bool converting(double t_s) const { return conversion_.has_value() && t_s < conversion_->end_s; }
  // The PROM as a read finds it (with the faults).
  Ms5611Prom served_prom() const;

 private:
  struct Conversion {
    bool pressure = false;
    size_t osr = 0;
    double start_s = 0;
    double end_s = 0;
    bool wrong = false;   // read early, or started over another: the result will be wrong
    bool sensed = false;  // has taken its pressure and temperature
    double pressure_pa = 0;
    double temperature_c = 0;
  };
  // One command byte; false when refused.
  bool command(uint8_t byte, double t_s);
  uint32_t result(const Conversion& c) const;
  void answer(uint32_t value, size_t bytes);

  uint8_t address_;
  Ms5611Prom prom_;
  Ms5611Faults faults_;
  double ready_s_ = 0;
  std::optional<Conversion> conversion_;
  std::array<uint8_t, 3> answer_{};  // what a read clocks out, most significant byte first
  size_t answer_bytes_ = 0;
  double pressure_pa_;  // the last sensed (ISA sea level at 15 °C until the first)
  double temperature_c_;
};

}  // namespace sim
