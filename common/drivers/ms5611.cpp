#include <common/drivers/ms5611.hpp>

namespace drivers {

Ms5611Reading compensate(const Ms5611Prom& prom, uint32_t d1, uint32_t d2) {
  Ms5611Reading r;
  if (d1 == 0 || d2 == 0 || d1 > kMs5611AdcMax || d2 > kMs5611AdcMax) return r;
  const int64_t c1 = prom.word[1], c2 = prom.word[2], c3 = prom.word[3], c4 = prom.word[4], c5 = prom.word[5];
  const int64_t dt = static_cast<int64_t>(d2) - (c5 << 8);  // 25 bits with its sign
  int64_t temp = 2000 + ((dt * prom.word[6]) >> 23);
  int64_t off = (c2 << 16) + ((c4 * dt) >> 7);   // 41 bits
  int64_t sens = (c1 << 15) + ((c3 * dt) >> 8);  // 41 bits
  if (temp < 2000) {
    const int64_t cold = (temp - 2000) * (temp - 2000);
    r.t2 = static_cast<int32_t>((dt * dt) >> 31);
    r.off2 = (5 * cold) >> 1;
    r.sens2 = (5 * cold) >> 2;
    if (temp < -1500) {
      const int64_t very_cold = (temp + 1500) * (temp + 1500);
      r.off2 += 7 * very_cold;
      r.sens2 += (11 * very_cold) >> 1;
    }
    temp -= r.t2;
    off -= r.off2;
    sens -= r.sens2;
  }
  // D1 < 2^24 and |SENS| < 2^38 even for a TEMP no chip gives: the product fits in 63 bits.
  const int64_t p = ((static_cast<int64_t>(d1) * sens >> 21) - off) >> 15;
  r.dt = static_cast<int32_t>(dt);
  r.temp_centi_c = static_cast<int32_t>(temp);
  r.off = off;
  r.sens = sens;
  r.pressure_pa = static_cast<int32_t>(p);
  r.in_range = temp >= kMs5611TempMinCentiC && temp <= kMs5611TempMaxCentiC && p >= kMs5611PressureMinPa &&
               p <= kMs5611PressureMaxPa;
  return r;
}

uint32_t Ms5611::total_faults() const {
  uint32_t total = 0;
  for (uint32_t n : faults_) total += n;
  return total;
}

bool Ms5611::next_transfer(uint32_t now_us, I2cTransfer& transfer) const {
  // Unsigned difference: right across the wrap of the microsecond clock.
  if (now_us - since_us_ < wait_us_) return false;
  const uint8_t address = config_.address;
  switch (phase_) {
    case Phase::reset: transfer = write_command(address, kMs5611Reset); return true;
    case Phase::prom:
      transfer = read_registers(address, static_cast<uint8_t>(kMs5611PromRead + 2 * prom_word_), 2);
      return true;
    case Phase::command: {
      const uint8_t offset = ms5611_osr_row(config_.osr).command_offset;
      transfer = write_command(address,
                               static_cast<uint8_t>((d2_next_ ? kMs5611ConvertD2 : kMs5611ConvertD1) + offset));
      return true;
    }
    case Phase::converting: transfer = read_registers(address, kMs5611AdcRead, kMs5611AdcBytes); return true;
  }
  return false;
}

void Ms5611::begun() {
  on_wire_ = true;
  switch (phase_) {
    case Phase::reset:
      ++resets_;
      state_ = Ms5611State::starting;
      bus_time_ns_ += kMs5611CommandNs;
      break;
    case Phase::command: bus_time_ns_ += kMs5611CommandNs; break;
    case Phase::prom: bus_time_ns_ += kMs5611PromWordNs; break;
    case Phase::converting: bus_time_ns_ += kMs5611AdcReadNs; break;
  }
}

void Ms5611::wait(Phase phase, uint32_t now_us, uint32_t wait_us) {
  phase_ = phase;
  since_us_ = now_us;
  wait_us_ = wait_us;
}

void Ms5611::start_over(Ms5611State state, uint32_t now_us) {
  state_ = state;
  have_d2_ = false;
  d2_next_ = true;
  faults_in_a_row_ = 0;
  wait(Phase::reset, now_us, kMs5611RestartDelayUs);
}

void Ms5611::fault(Ms5611Fault kind, uint32_t now_us) {
  ++faults_[static_cast<size_t>(kind)];
  last_fault_ = kind;
  if (state_ != Ms5611State::measuring) {
    // Before the PROM is known good the chip cannot be trusted with a conversion: start over.
    start_over(kind == Ms5611Fault::prom_crc ? Ms5611State::prom_bad : Ms5611State::restarting, now_us);
    return;
  }
  if (++faults_in_a_row_ >= kMs5611FaultsBeforeRestart) {
    start_over(Ms5611State::restarting, now_us);
    return;
  }
  // The failed transfer may have started a conversion (or left one running): let it end before
  // the next command, which is the same conversion again.
  wait(Phase::command, now_us, conversion_us_);
}

void Ms5611::finished(I2cResult result, const I2cReply& reply, uint32_t now_us) {
  on_wire_ = false;
  switch (result) {
    case I2cResult::ok: completed(reply, now_us); return;
    case I2cResult::address_nack: fault(Ms5611Fault::address_nack, now_us); return;
    case I2cResult::data_nack: fault(Ms5611Fault::data_nack, now_us); return;
    case I2cResult::bus_stuck: fault(Ms5611Fault::bus_stuck, now_us); return;
    case I2cResult::idle:
    case I2cResult::pending: break;
  }
  fault(Ms5611Fault::bad_reply, now_us);  // the bus forgot the transfer (or answered nonsense)
}

void Ms5611::completed(const I2cReply& reply, uint32_t now_us) {
  switch (phase_) {
    case Phase::reset:
      prom_word_ = 0;
      wait(Phase::prom, now_us, kMs5611ResetTimeUs);
      return;
    case Phase::prom: {
      if (reply.count != 2) return fault(Ms5611Fault::bad_reply, now_us);
      prom_.word[prom_word_] = static_cast<uint16_t>((reply.data[0] << 8) | reply.data[1]);
      if (++prom_word_ < kMs5611PromWords) return wait(Phase::prom, now_us, 0);
      if (!ms5611_prom_valid(prom_)) return fault(Ms5611Fault::prom_crc, now_us);
      state_ = Ms5611State::measuring;
      faults_in_a_row_ = 0;
      return wait(Phase::command, now_us, 0);
    }
    case Phase::command: command_done_us_ = now_us; return wait(Phase::converting, now_us, conversion_us_);
    case Phase::converting: {
      if (reply.count != kMs5611AdcBytes) return fault(Ms5611Fault::bad_reply, now_us);
      const uint32_t value = (uint32_t{reply.data[0]} << 16) | (uint32_t{reply.data[1]} << 8) | reply.data[2];
      if (value == 0) return fault(Ms5611Fault::adc_zero, now_us);
      return converted(value, now_us);
    }
  }
}

void Ms5611::converted(uint32_t value, uint32_t now_us) {
  if (d2_next_) {
    const int32_t temp = ms5611_first_order_temp(prom_, value);
    if (temp < kMs5611TempMinCentiC || temp > kMs5611TempMaxCentiC) return fault(Ms5611Fault::out_of_range, now_us);
    d2_ = value;
    have_d2_ = true;
    d2_next_ = false;
    pressures_since_d2_ = 0;
    return wait(Phase::command, now_us, 0);
  }
  const Ms5611Reading r = compensate(prom_, value, d2_);
  if (!have_d2_ || !r.in_range) return fault(Ms5611Fault::out_of_range, now_us);
  reading_ = r;
  reading_time_us_ = command_done_us_;
  ++readings_;
  faults_in_a_row_ = 0;
  d2_next_ = ++pressures_since_d2_ >= config_.pressures_per_temperature;
  wait(Phase::command, now_us, 0);
}

}  // namespace drivers
