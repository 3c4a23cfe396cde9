// A scripted stand-in for the QR, built from the wire library: it parses what the console sends,
// answers requests (with the QR's dedup, so resends are answered and not applied twice), keeps a
// small safety machine (modes entered from safe with neutral controls, calibration first for yaw
// and full, panic then safe, link loss panics, a motor test's engine for 2 s), sends telemetry,
// runs the observable streams asked for (made-up values: stream_wave) and serves logs. Tests
// script it:
// silence it, make it refuse, drop log parts. Not the firmware: the end-to-end test flies that.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <functional>
#include <map>
#include <optional>
#include <vector>

#include <common/frame_parser.hpp>
#include <common/messages.hpp>
#include <common/parameter_table.hpp>
#include <common/request_dedup.hpp>
#include <common/sample_packing.hpp>

namespace qrterm_test {

class FakeQr {
 public:
  static constexpr uint32_t kCalibrationMs = 500;
  static constexpr uint32_t kPanicMs = 1000;
  static constexpr uint32_t kMotorTestMs = 2000;
  static constexpr uint32_t kLinkTimeoutMs = 250;
  static constexpr uint32_t kTelemetryPeriodMs = 20;
  static constexpr uint16_t kLogCapacity = 2340;

  explicit FakeQr(uint32_t now_ms) : last_frame_ms_(now_ms), next_telemetry_ms_(now_ms) {}

  void receive(const uint8_t* data, size_t count, uint32_t now_ms);
  void receive(const std::vector<uint8_t>& bytes, uint32_t now_ms) { receive(bytes.data(), bytes.size(), now_ms); }
  // Telemetry every kTelemetryPeriodMs (unless silent), the panic timeline, calibration, link loss.
  void tick(uint32_t now_ms);
  std::vector<uint8_t> take_output();

  // Sends a debug text line now, in pieces.
  void say(const char* text);

  // --- the script
  bool silent = false;          // sends nothing at all (a dead QR)
  bool answer_requests = true;  // false: requests are received but never answered
  bool telemetry = true;
  bool report_after_set = true;  // protocol.md: a param_report follows every accepted param_set
  std::function<bool(uint16_t line, uint8_t part)> drop_log_part;  // true: that part is lost
  std::map<uint16_t, wire::SensorLogRecord> sensor_log;            // lines 0..size-1
  std::map<uint16_t, wire::TelemetryLogRecord> telemetry_log;
  bool logging = false;
  bool flying_flag = false;                     // the flying/landed verdict's telemetry flag
  std::optional<wire::TelemetryHeight> height;  // sent every telemetry period when set
  // Not none: every request to leave safe is refused with it (as the firmware's sensor faults,
  // docs/safety.md rule 20, refuse with imu_fault).
  wire::NackReason refuse_leaving_safe = wire::NackReason::none;
  bool observable_table = false;           // answers observable_get with the table (the plot's names)
  std::vector<wire::TelemetryTask> tasks;  // one sent per telemetry period, in turn, when any

  // --- what it has seen and what it is
  wire::Mode mode = wire::Mode::safe;
  bool calibrated = false;
  bool exited = false;
  wire::Control control;
  wire::ParameterValues params;
  uint32_t controls_received = 0;
  std::vector<wire::Frame> requests;  // every request frame received, resends included
  uint32_t requests_applied = 0;
  uint16_t engine[4] = {0, 0, 0, 0};
  const wire::LinkCounters& counters() const { return parser_.counters(); }

 private:
  struct Handler;
  friend struct Handler;

  wire::NackReason apply(const wire::Frame& frame);
  void resend_log_parts(const wire::LogResend& r);
  wire::NackReason change_mode(wire::Mode wanted);
  void send(const wire::FrameBytes& frame);
  void send_telemetry();
  void send_samples();
  void send_log(wire::LogKind log, uint16_t first, uint16_t count);
  void update_engines();
  uint8_t test_engine_ = 0;  // the motor test's engine and level
  uint16_t test_level_ = 0;
  wire::LogStatus log_status() const;

  wire::FrameParser parser_{wire::Listen::pc_to_qr};
  wire::RequestDedup dedup_;
  std::vector<uint8_t> output_;
  uint32_t now_ms_ = 0;
  uint32_t last_frame_ms_;
  uint32_t next_telemetry_ms_;
  uint32_t mode_since_ms_ = 0;
  uint8_t tick_ = 0;
  uint8_t slow_group_ = 0;
  size_t next_task_ = 0;
  // A stream as last asked (divider 0: stopped), sampled every divider control periods (1 ms).
  struct Stream {
    wire::StreamRequest asked;
    wire::SamplePacker packer;
    uint32_t next_ms = 0;
  };
  Stream streams_[wire::kStreamCount];
};

// What the fake's streams carry for an observable at a time, raw as on the wire: phi swings
// 0.1 rad every 2 s and height 0.5 m about 5 m every 4 s (an angle and a height far apart in
// size, for the plot's per-unit axes), every other observable reads 0.
int16_t stream_wave(uint8_t id, uint32_t t_ms);

}  // namespace qrterm_test
