// What the QR tells the console every telemetry period (docs/protocol.md section 7): attitude and
// rates always; engines, set-points, system, link and log status in turn; one task's figures.
#pragma once

#include <stdint.h>

#include <common/messages.hpp>
#include <common/units.hpp>
#include <qr/core/flight_types.hpp>
#include <qr/core/observable_readers.hpp>
#include <qr/core/scheduler.hpp>

namespace qr {

class FlightTelemetry {
 public:
  // After every tick: the longest since the last system report, and the scheduler's figures.
  void note_tick(const TickReport& report) {
    if (report.busy_us > loop_time_us_) loop_time_us_ = report.busy_us;
    deadline_misses_ = report.deadline_misses;
    cpu_load_permille_ = report.cpu_load_permille;
  }
  uint16_t cpu_load_permille() const { return cpu_load_permille_; }
  uint32_t deadline_misses() const { return deadline_misses_; }

  // One telemetry period's frames from the flight's read-outs, each handed to `send`. The attitude,
  // rates, set-points and climb are those observables' values (observable_readers.hpp).
  template <class Flight, class Send>
  void period(const Flight& f, Send&& send) {
    send(wire::encode(wire::TelemetryAttitude{seq_++, f.mode(), f.telemetry_flags(), observe<Id::phi>(f),
                                              observe<Id::theta>(f), observe<Id::psi>(f)}));
    send(wire::encode(wire::TelemetryRates{observe<Id::p>(f), observe<Id::q>(f), observe<Id::r>(f)}));
    slow_group(f, send);
    if (f.task_stats() != nullptr) {
      const TaskStats& c = f.task_stats()->task[stats_task_];
      send(wire::encode(wire::TelemetryTask{stats_task_, wire::saturate_u16(c.mean()), wire::saturate_u16(c.max),
                                            wire::saturate_u16(c.overruns)}));
      stats_task_ = static_cast<uint8_t>(stats_task_ + 1 == Flight::kTaskCount ? 0 : stats_task_ + 1);
    }
  }

 private:
  // Engines, set-points, system, link, log status and height take turns, each at a sixth of the
  // rate; the radio's link and the engines' RPM take a turn of their own once there is one to
  // report (a turn each keeps a period's work the most any one turn costs: the task's budget).
  template <class Flight, class Send>
  void slow_group(const Flight& f, Send& send) {
    const bool radio = f.radio().heard() || f.pilot() == Pilot::radio;
    wire::TelemetryRpm rpm;
    const bool rpm_known = f.rpm(rpm.rpm);
    const uint8_t group = slow_group_;
    do {
      slow_group_ = static_cast<uint8_t>(slow_group_ == kRpmGroup ? 0 : slow_group_ + 1);
    } while ((slow_group_ == kRadioGroup && !radio) || (slow_group_ == kRpmGroup && !rpm_known));
    if (group == 0) {
      wire::TelemetryEngines m;
      for (int i = 0; i < 4; ++i) m.engine[i] = f.engines().value[i];
      send(wire::encode(m));
    } else if (group == 1) {
      send(wire::encode(wire::TelemetrySetpoints{f.controls().lift, observe<Id::phi_sp>(f), observe<Id::theta_sp>(f),
                                                 observe<Id::r_sp>(f)}));
    } else if (group == 2) {
      const uint16_t loop = wire::saturate_u16(loop_time_us_);
      loop_time_us_ = 0;
      send(wire::encode(wire::TelemetrySystem{f.sample().battery_mv, cpu_load_permille_, loop,
                                              static_cast<uint16_t>(deadline_misses_)}));
    } else if (group == 4) {
      send(wire::encode(f.log().status()));
    } else if (group == 5) {
      const auto& chain = f.chain();
      send(wire::encode(wire::TelemetryHeight{chain.height_mm(), observe<Id::climb>(f),
                                              chain.height_valid() ? wire::kHeightValid : uint8_t{0},
                                              chain.hover_lift()}));
    } else if (group == kRadioGroup) {
      if (radio) send(wire::encode(radio_report(f)));
    } else if (group == kRpmGroup) {
      if (rpm_known) send(wire::encode(rpm));
    } else {
      const wire::LinkCounters& c = f.link_counters();
      send(wire::encode(wire::TelemetryLink{static_cast<uint16_t>(c.frames_ok), static_cast<uint16_t>(c.check_failures),
                                            static_cast<uint16_t>(c.unknown_types),
                                            static_cast<uint16_t>(c.bytes_skipped),
                                            static_cast<uint8_t>(f.rx_overruns() < 255u ? f.rx_overruns() : 255u)}));
    }
  }

  using Id = wire::ObservableId;
  static constexpr uint8_t kRadioGroup = 6;
  static constexpr uint8_t kRpmGroup = 7;

  template <class Flight>
  static wire::TelemetryRadio radio_report(const Flight& f) {
    const auto& st = f.radio().stats();
    wire::TelemetryRadio m;
    m.flags = static_cast<uint8_t>((f.pilot() == Pilot::radio ? wire::kRadioPilot : 0) |
                                   (f.radio_link_up() ? wire::kRadioLinkUp : 0) |
                                   (f.safety().arm_switch() ? wire::kRadioArmSwitch : 0));
    m.uplink_rssi = st.active_antenna == 0 ? st.uplink_rssi_ant1 : st.uplink_rssi_ant2;
    m.uplink_lq = st.uplink_link_quality > 100 ? uint8_t{100} : st.uplink_link_quality;
    m.uplink_snr = st.uplink_snr;
    m.rf_mode = st.rf_mode;
    m.tx_power = st.uplink_tx_power;
    m.downlink_rssi = st.downlink_rssi;
    m.downlink_lq = st.downlink_link_quality > 100 ? uint8_t{100} : st.downlink_link_quality;
    m.downlink_snr = st.downlink_snr;
    return m;
  }

  uint8_t seq_ = 0;
  uint8_t slow_group_ = 0;
  uint8_t stats_task_ = 0;     // whose figures the next telemetry_task carries
  uint32_t loop_time_us_ = 0;  // longest tick since the last system report
  uint32_t deadline_misses_ = 0;
  uint16_t cpu_load_permille_ = 0;
};

}  // namespace qr
