// The golden frames: one or more per message type, each with the exact bytes docs/protocol.md
// lists for it. golden_frames_test checks the encoder against the hex, the decoder against the
// message, and that the document lists exactly these frames.
#pragma once

#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include <common/messages.hpp>
#include <common/parameter_table.hpp>

namespace wire_test {

struct GoldenFrame {
  std::string id;
  std::string hex;  // as written in docs/protocol.md
  wire::MessageType type;
  wire::FrameBytes encoded;                                    // what the encoder makes of the message
  std::function<bool(const wire::Frame&)> decodes_to_message;  // decode(frame) == the message
};

template <wire::Message Msg>
GoldenFrame golden(std::string id, const Msg& message, std::string hex) {
  return GoldenFrame{std::move(id), std::move(hex), Msg::kType, wire::encode(message),
                     [message](const wire::Frame& frame) {
                       Msg decoded;
                       return wire::decode(frame, decoded) && decoded == message;
                     }};
}

inline wire::SensorLogRecord golden_sensor_record() {
  wire::SensorLogRecord r;
  r.line = 1000;
  r.time_us = 123456789;
  r.gyro[0] = -12, r.gyro[1] = 7, r.gyro[2] = 300;
  r.accel[0] = 250, r.accel[1] = -180, r.accel[2] = 16384;
  r.gyro_filtered[0] = -10, r.gyro_filtered[1] = 5, r.gyro_filtered[2] = 298;
  r.accel_filtered[0] = 248, r.accel_filtered[1] = -177, r.accel_filtered[2] = 16380;
  r.battery_mv = 11850;
  return r;
}

inline wire::TelemetryLogRecord golden_telemetry_record() {
  wire::TelemetryLogRecord r;
  r.line = 17;
  r.time_us = 5000000;
  r.mode = wire::Mode::full_control;
  r.flags = wire::kFlagCalibrated | wire::kFlagLogging;
  r.lift = 450, r.roll = -873, r.pitch = 0, r.yaw_rate = 500;
  r.phi = -850, r.theta = 12, r.psi = 31416;
  r.p = -20, r.q = 3, r.r = 495;
  r.engine[0] = 400, r.engine[1] = 410, r.engine[2] = 395, r.engine[3] = 405;
  r.loop_time_us = 612, r.battery_mv = 11850, r.cpu_load = 623, r.deadline_misses = 3;
  return r;
}

// G35's request: the parts named by their bit numbers (docs/protocol.md, log_resend).
inline wire::LogResend log_resend(uint8_t seq, wire::LogKind log, uint16_t first_line,
                                  std::initializer_list<size_t> bits) {
  wire::LogResend r{seq, log, first_line, {}};
  for (size_t bit : bits) r.want(bit);
  return r;
}

inline std::vector<GoldenFrame> golden_frames() {
  using namespace wire;
  DebugText text;
  text.fill("mode 2\n", 7);
  return {
      golden("G1", Control{500, -250, 100, 0}, "4D 11 F4 01 06 FF 64 00 00 00 98"),
      golden("G2", ModeChange{7, Mode::manual}, "4D 12 07 02 30 99 09 24"),
      golden("G3", ParamSet{3, static_cast<uint8_t>(ParamId::battery_panic_mv), 10500},
             "4D 14 03 0A 04 29 00 00 1C 01 F0 4B"),
      golden("G4", ParamGet{4, kAllParameters}, "4D 17 04 FF EF"),
      golden("G5", LogStart{1, kLogSensor | kLogTelemetry}, "4D 18 01 03 8C 4D 55 42"),
      golden("G6", LogStop{2}, "4D 1B 02 CF 8D 92 82"),
      golden("G7", LogDownload{5, LogKind::telemetry, 120, 40}, "4D 1D 05 01 78 00 28 00 32"),
      golden("G8", Exit{9}, "4D 1E 09 93 6B 45 0C"),
      golden("G9", Ack{MessageType::mode_change, 7}, "4D 81 12 07 B9"),
      golden("G10", Nack{MessageType::mode_change, 8, NackReason::controls_not_neutral}, "4D 82 12 08 02 3C"),
      golden("G11", ParamReport{static_cast<uint8_t>(ParamId::battery_panic_mv), 10500}, "4D 84 0A 04 29 00 00 E1"),
      golden("G12", text, "4D 87 6D 6F 64 65 20 32 0A 00 00 87"),
      golden("G13", TelemetryAttitude{42, Mode::full_control, kFlagCalibrated | kFlagLogging, 1234, -567, 31416},
             "4D 88 2A 05 03 D2 04 C9 FD B8 7A 35"),
      golden("G14", TelemetryRates{-1500, 250, 3000}, "4D 8B 24 FA FA 00 B8 0B B0"),
      golden("G15", TelemetryEngines{{400, 410, 395, 405}}, "4D 8D 90 01 9A 01 8B 01 95 01 8E"),
      golden("G16", TelemetrySetpoints{450, -873, 0, 500}, "4D 8E C2 01 97 FC 00 00 F4 01 E5"),
      golden("G17", TelemetrySystem{11850, 623, 612, 3}, "4D 90 4A 2E 6F 02 64 02 03 00 A0"),
      golden("G18", TelemetryLink{5012, 3, 1, 27, 2}, "4D 93 94 13 03 00 01 00 1B 00 02 0C"),
      golden("G19", make_log_part(golden_sensor_record(), 0), "4D 95 E8 03 00 15 CD 5B 07 F4 FF 6E"),
      golden("G20", make_log_part(golden_sensor_record(), 4), "4D 95 E8 03 04 4F FF FC 3F 4A 2E A2"),
      golden("G21", make_log_part(golden_telemetry_record(), 0), "4D 96 11 00 00 40 4B 4C 00 05 03 AC"),
      golden("G22", make_log_part(golden_telemetry_record(), 6), "4D 96 11 00 06 4A 2E 6F 02 03 00 84"),
      golden("G23", TelemetryTask{7, 212, 530, 3}, "4D 99 07 D4 00 12 02 03 00 BB"),
      golden("G24", LogStatus{0x03, 1200, 1190, 2340}, "4D 9C 03 B0 04 A6 04 24 09 0E"),
      // The dedup's content rule (section 6): one seq, two requests.
      golden("G25", ModeChange{17, Mode::manual}, "4D 12 11 02 17 31 A9 C5"),
      golden("G26", ModeChange{17, Mode::panic}, "4D 12 11 01 E1 A8 A5 B2"),
      golden("G27", Ack{MessageType::mode_change, 17}, "4D 81 12 11 6A"),
      golden("G28", TelemetryHeight{1523, -412, kHeightValid, 548}, "4D 9F F3 05 00 00 64 FE 01 24 02 28"),
      golden("G29", ObservableGet{6, kAllObservables}, "4D 22 06 FF 22"),
      golden("G30", StreamRequest{8, 0, 5, {0, 6, kNoObservable, kNoObservable}}, "4D 41 08 00 05 00 00 06 FF FF 34"),
      golden("G31", ObservableInfo{0, 68, ObservableType::i16, -4, 1000}, "4D EB 00 44 00 FC E8 03 1E"),
      golden("G32", ObservableText{0, 0, {'p', 'h', 'i', ' ', 'r', 'a', 'd'}}, "4D E7 00 00 70 68 69 20 72 61 64 89"),
      golden("G33", ObservableSamples{sample_header(0, 5), {1234, 1500, 1250, 1500}},
             "4D E8 05 D2 04 DC 05 E2 04 DC 05 1B"),
      golden("G34", Nack{MessageType::stream_request, 9, NackReason::over_budget}, "4D 82 41 09 0C B2"),
      golden("G35", log_resend(6, LogKind::telemetry, 120, {3, 9, 34}), "4D 6C 06 01 78 00 08 02 00 00 04 F3"),
      golden("G36", TelemetryRadio{kRadioPilot | kRadioLinkUp, 60, 100, 9, 5, 3, 70, 98, -4},
             "4D A0 03 3C 64 09 05 03 46 62 FC 68"),
      golden("G37", TelemetryRpm{{20026, 19873, 20110, 19950}}, "4D A3 3A 4E A1 4D 8E 4E EE 4D B3"),
      golden("G38", MotorTest{10, 1, 100}, "4D 77 0A 01 64 00 AA 6F 90 B1"),
      golden("G39", EscDirection{11, 2, 2}, "4D 7B 0B 02 02 F1 1B D7 5C"),
  };
}

}  // namespace wire_test
