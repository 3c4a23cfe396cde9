#include <sim/ms5611_model.hpp>

#include <algorithm>
#include <cmath>

#include <sim/barometer.hpp>

namespace sim {
namespace {

constexpr double kTwo7 = 128.0, kTwo8 = 256.0, kTwo15 = 32768.0, kTwo16 = 65536.0, kTwo21 = 2097152.0,
                 kTwo23 = 8388608.0, kTwo30 = 1073741824.0, kTwo31 = 2147483648.0;
constexpr double kMaxCode = 16777215.0;  // 2^24 - 1

uint32_t to_code(double value) { return static_cast<uint32_t>(std::clamp(std::nearbyint(value), 0.0, kMaxCode)); }

}  // namespace

uint8_t ms5611_crc4(const Ms5611Prom& prom) {
  uint16_t remainder = 0;
  for (size_t i = 0; i < 16; ++i) {
    const uint16_t word = i / 2 == 7 ? static_cast<uint16_t>(prom[7] & 0xFF00) : prom[i / 2];
    // Each word's most significant byte first.
    remainder ^= static_cast<uint16_t>(i % 2 == 0 ? word >> 8 : word & 0x00FF);
    for (int bit = 0; bit < 8; ++bit) {
      const bool top = (remainder & 0x8000) != 0;
      remainder = static_cast<uint16_t>(remainder << 1);
      if (top) remainder ^= 0x3000;
    }
  }
  return static_cast<uint8_t>((remainder >> 12) & 0x000F);
}

Ms5611Prom ms5611_example_prom() {
  Ms5611Prom prom = {0x0000, 40127, 36924, 23317, 23282, 33464, 28312, 0x4B00};
  prom[7] = static_cast<uint16_t>(prom[7] | ms5611_crc4(prom));
  return prom;
}

// The datasheet's compensation, run backwards. Temperature: TEMP = 2000 + dT C6 / 2^23 (0.01 °C),
// less T2 = dT² / 2^31 below 20 °C, so below 20 °C dT is the negative root of
// dT² / 2^31 - (C6 / 2^23) dT + (TEMP - 2000) = 0. Pressure: P = (D1 SENS / 2^21 - OFF) / 2^15 with
// OFF and SENS (and their second-order terms) from the dT of the rounded D2, the one a driver
// will compute from, so that only D1's own rounding (about 0.02 Pa) is left.
Ms5611Codes ms5611_codes(const Ms5611Prom& prom, double pressure_pa, double temperature_c) {
  const double c1 = prom[1], c2 = prom[2], c3 = prom[3], c4 = prom[4], c5 = prom[5], c6 = prom[6];
  const double temp = temperature_c * 100.0;
  const double slope = c6 / kTwo23;
  const double dt_wanted = temp >= 2000.0
                               ? (temp - 2000.0) / slope
                               : (slope - std::sqrt(slope * slope + 4.0 * (2000.0 - temp) / kTwo31)) * kTwo30;
  Ms5611Codes codes;
  codes.d2 = to_code(dt_wanted + c5 * kTwo8);

  const double dt = static_cast<double>(codes.d2) - c5 * kTwo8;
  const double temp1 = 2000.0 + dt * slope;  // first order
  double off = c2 * kTwo16 + c4 * dt / kTwo7;
  double sens = c1 * kTwo15 + c3 * dt / kTwo8;
  if (temp1 < 2000.0) {
    const double below20 = (temp1 - 2000.0) * (temp1 - 2000.0);
    double off2 = 5.0 * below20 / 2.0, sens2 = 5.0 * below20 / 4.0;
    if (temp1 < -1500.0) {
      const double below_minus15 = (temp1 + 1500.0) * (temp1 + 1500.0);
      off2 += 7.0 * below_minus15;
      sens2 += 11.0 * below_minus15 / 2.0;
    }
    off -= off2;
    sens -= sens2;
  }
  codes.d1 = to_code((pressure_pa * kTwo15 + off) * kTwo21 / sens);
  return codes;
}

Ms5611Model::Ms5611Model(uint8_t address, const Ms5611Prom& prom, double power_on_s)
    : address_(address), prom_(prom), ready_s_(power_on_s + kResetS), pressure_pa_(kIsaSeaLevelPa),
      temperature_c_(kIsaSeaLevelK - 273.15) {}

Ms5611Prom Ms5611Model::served_prom() const {
  Ms5611Prom prom = prom_;
  if (faults_.bad_prom_crc) prom[7] ^= 0x0001;
  return prom;
}

I2cAck Ms5611Model::write(const uint8_t* bytes, size_t n, double t_s) {
  if (!answers(t_s)) return I2cAck::address_nack;
  for (size_t i = 0; i < n; ++i) {
    // A byte after a reset finds the chip reloading its PROM.
    if (!answers(t_s) || !command(bytes[i], t_s)) return I2cAck::data_nack;
  }
  return I2cAck::ack;
}

I2cAck Ms5611Model::read(uint8_t* out, size_t n, double t_s) {
  if (!answers(t_s)) {
    std::fill(out, out + n, static_cast<uint8_t>(0xFF));
    return I2cAck::address_nack;
  }
  for (size_t i = 0; i < n; ++i) out[i] = i < answer_bytes_ ? answer_[i] : 0;
  return I2cAck::ack;
}

bool Ms5611Model::command(uint8_t byte, double t_s) {
  const size_t osr = static_cast<size_t>((byte & 0x0F) / 2);
  const bool even = (byte & 0x01) == 0;
  if (byte == kReset) {
    conversion_.reset();
    answer_bytes_ = 0;
    ready_s_ = t_s + kResetS;
  } else if (even && osr < kConversionS.size() && (byte & 0xF0) == (kConvertD1 & 0xF0)) {
    conversion_ = Conversion{true, osr, t_s, t_s + kConversionS[osr] + faults_.slow_conversion_s, converting(t_s)};
  } else if (even && osr < kConversionS.size() && (byte & 0xF0) == (kConvertD2 & 0xF0)) {
    conversion_ = Conversion{false, osr, t_s, t_s + kConversionS[osr] + faults_.slow_conversion_s, converting(t_s)};
  } else if (byte == kAdcRead) {
    if (conversion_ && converting(t_s)) {
      conversion_->wrong = true;  // "the conversion will not stop and the final result will be wrong"
      answer(0, 3);
    } else if (conversion_) {
      answer(result(*conversion_), 3);
      conversion_.reset();  // a repeated ADC read gives 0
    } else {
      answer(0, 3);
    }
  } else if (even && (byte & 0xF0) == (kPromRead & 0xF0)) {
    answer(served_prom()[(byte & 0x0F) / 2], 2);
  } else {
    return false;
  }
  return true;
}

void Ms5611Model::answer(uint32_t value, size_t bytes) {
  answer_bytes_ = bytes;
  for (size_t i = 0; i < bytes; ++i) answer_[i] = static_cast<uint8_t>(value >> (8 * (bytes - 1 - i)));
}

uint32_t Ms5611Model::result(const Conversion& c) const {
  const double pressure_pa = c.sensed ? c.pressure_pa : pressure_pa_;
  const double temperature_c = c.sensed ? c.temperature_c : temperature_c_;
  const Ms5611Codes codes = ms5611_codes(prom_, pressure_pa, temperature_c);
  const uint32_t code = c.pressure ? codes.d1 : codes.d2;
  return c.wrong ? code / 2 : code;
}

void Ms5611Model::sense(double t_s, double pressure_pa, double temperature_c) {
  pressure_pa_ = pressure_pa;
  temperature_c_ = temperature_c;
  if (const std::optional<double> at = next_sample_s(); at && t_s >= *at) {
    conversion_->sensed = true;
    conversion_->pressure_pa = pressure_pa;
    conversion_->temperature_c = temperature_c;
  }
}

std::optional<double> Ms5611Model::next_sample_s() const {
  if (!conversion_ || conversion_->sensed) return std::nullopt;
  return 0.5 * (conversion_->start_s + conversion_->end_s);
}

double Ms5611Model::noise_scale() const {
  return conversion_ ? kResolutionPa[conversion_->osr] / kResolutionPa.back() : 1.0;
}

}  // namespace sim
