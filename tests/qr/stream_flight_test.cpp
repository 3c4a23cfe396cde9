// Observable streams in the flight (docs/protocol.md section 13): the table over the wire, a
// stream's samples at its rate, the budget refusal, and what the line really carries with the
// largest selection the budget accepts. The console's side of the line is emulated at 115200
// baud, so a rule that promised more than the line carries would show as lost samples or a
// growing backlog.
#include <gtest/gtest.h>

#include <cstdio>
#include <deque>
#include <map>
#include <string>
#include <vector>

#include <common/drivers/erpm.hpp>
#include <common/messages.hpp>
#include <common/sample_packing.hpp>

#include "fake_flight.hpp"

namespace qr {
namespace {

using test::Firmware;

struct StreamFlightTest : test::FakeFlight<> {
  std::deque<uint8_t> line;  // bytes on their way at 115200 baud
  size_t line_backlog_max = 0;
  uint32_t line_credit_milli = 0;  // thousandths of a byte the line may still carry

  // Runs `ms` with the console's control at 50 Hz; the QR's bytes reach the console at line speed.
  void run_ms(uint32_t ms) {
    for (uint32_t t = 0; t < ms; ++t) {
      if (t % 20 == 0) send(wire::Control{});
      pass_ms();
      line.insert(line.end(), board.tx.begin(), board.tx.end());
      board.tx.clear();
      line_credit_milli += 115200 / 10;  // bytes per second = thousandths of a byte per ms
      while (line_credit_milli >= 1000 && !line.empty()) {
        line_credit_milli -= 1000;
        pc.push(line.front(), [&](const wire::Frame& f) { received.push_back(f); });
        line.pop_front();
      }
      if (line.empty()) line_credit_milli = 0;  // an idle line saves nothing up
      line_backlog_max = std::max(line_backlog_max, line.size());
    }
  }
  wire::NackReason answer_to(uint8_t request_seq) const {
    for (const auto& a : got<wire::Ack>())
      if (a.type == wire::MessageType::stream_request && a.seq == request_seq) return wire::NackReason::none;
    for (const auto& n : got<wire::Nack>())
      if (n.type == wire::MessageType::stream_request && n.seq == request_seq) return n.reason;
    ADD_FAILURE() << "no answer to stream request " << int(request_seq);
    return wire::NackReason::bad_value;
  }
  uint8_t request_stream(uint8_t stream, uint16_t divider, std::vector<uint8_t> ids) {
    wire::StreamRequest r;
    r.seq = ++seq;
    r.stream = stream;
    r.divider = divider;
    for (size_t i = 0; i < ids.size(); ++i) r.id[i] = ids[i];
    send(r);
    return r.seq;
  }
};

TEST_F(StreamFlightTest, TheWholeTableComesOverTheWireWithNamesAndUnits) {
  send(wire::ObservableGet{++seq, wire::kAllObservables});
  // A row a tick while the line has room: 84 rows of about four frames each, some 0.4 s at
  // 1 kHz and twice that at 500 Hz.
  run_ms(1500);
  std::map<uint8_t, wire::ObservableInfo> info;
  for (const auto& i : got<wire::ObservableInfo>()) info[i.id] = i;
  std::map<uint8_t, std::string> text;
  for (const auto& t : got<wire::ObservableText>()) {
    std::string& s = text[t.id];
    const size_t needed = size_t{t.part + 1u} * wire::kObservableTextPartChars;
    if (s.size() < needed) s.resize(needed, '\0');
    for (size_t i = 0; i < wire::kObservableTextPartChars; ++i)
      s[t.part * wire::kObservableTextPartChars + i] = t.text[i];
  }
  ASSERT_EQ(info.size(), size_t{wire::kObservableCount});
  for (const wire::ObservableSpec& spec : wire::kObservableTable) {
    const uint8_t id = static_cast<uint8_t>(spec.id);
    EXPECT_EQ(info[id].count, wire::kObservableCount);
    EXPECT_EQ(info[id].scale, spec.scale) << spec.name;
    EXPECT_EQ(info[id].type, spec.type) << spec.name;
    EXPECT_EQ(info[id].control_hz, kControlHz);
    EXPECT_EQ(std::string(text[id].c_str()), std::string(spec.name) + " " + spec.unit);
  }
  EXPECT_EQ(flight.tx_dropped_frames(), 0u) << "the table waits for room beside the telemetry";
}

TEST_F(StreamFlightTest, AStreamSamplesAtItsDividerTheValuesOfTheTick) {
  const uint16_t divider = static_cast<uint16_t>(kControlHz / 100);  // 100 Hz at either control rate
  const uint8_t s = request_stream(
      1, divider, {static_cast<uint8_t>(wire::ObservableId::phi), static_cast<uint8_t>(wire::ObservableId::battery)});
  run_ms(1000);
  EXPECT_EQ(answer_to(s), wire::NackReason::none);
  wire::SampleUnpacker unpacker;
  unpacker.start(2);
  std::vector<std::pair<int16_t, uint16_t>> samples;
  for (const auto& frame : got<wire::ObservableSamples>()) {
    ASSERT_EQ(frame.stream(), 1);
    unpacker.unpack(frame, [&](const int16_t* v) { samples.push_back({v[0], static_cast<uint16_t>(v[1])}); });
  }
  EXPECT_NEAR(static_cast<double>(samples.size()), 100.0, 4.0);
  EXPECT_EQ(unpacker.lost(), 0u);
  ASSERT_FALSE(samples.empty());
  EXPECT_EQ(samples.back().first, 123) << "the scripted chain's roll";
  EXPECT_EQ(samples.back().second, 12000) << "battery in mV, as u16";

  // Stopped: nothing more comes.
  const uint8_t stop = request_stream(1, 0, {});
  run_ms(20);
  EXPECT_EQ(answer_to(stop), wire::NackReason::none);
  const size_t before = got<wire::ObservableSamples>().size();
  run_ms(200);
  EXPECT_EQ(got<wire::ObservableSamples>().size(), before);
}

TEST_F(StreamFlightTest, ASelectionTheLineCannotCarryIsRefusedAndChangesNothing) {
  // 250 Hz: 3000 bytes/s; then every tick: 12 bytes a tick, 6000 or 12000 bytes/s; beside the
  // first, over the 8370 there is room for at 50 Hz telemetry.
  const uint8_t fits = request_stream(0, static_cast<uint16_t>(kControlHz / 250), {0, 1, 2, 3});
  const uint8_t too_much = request_stream(1, 1, {0, 1, 2, 3});
  const uint8_t unknown = request_stream(2, 5, {wire::kObservableCount});
  run_ms(300);
  EXPECT_EQ(answer_to(fits), wire::NackReason::none);
  EXPECT_EQ(answer_to(too_much), wire::NackReason::over_budget);
  EXPECT_EQ(answer_to(unknown), wire::NackReason::bad_value);
  for (const auto& frame : got<wire::ObservableSamples>()) EXPECT_EQ(frame.stream(), 0) << "stream 1 never started";
}

// The controllers' terms are read where the chain keeps them, each row from its own term and
// axis (the scripted chain gives every one a different value), in the row's wire units.
TEST_F(StreamFlightTest, ControllerTermsAreReadFromTheirOwnTermAndAxis) {
  run_ms(10);
  using wire::ObservableId;
  const std::pair<ObservableId, int32_t> expected[] = {
      {ObservableId::p_sp, 100},
      {ObservableId::q_sp, 101},
      {ObservableId::roll_p_term, 200},
      {ObservableId::roll_d_term, -300},
      {ObservableId::roll_integral, 400},
      {ObservableId::pitch_p_term, 201},
      {ObservableId::pitch_d_term, -301},
      {ObservableId::pitch_integral, 401},
      {ObservableId::yaw_p_term, 202},
      {ObservableId::yaw_integral, 402},
      {ObservableId::roll_moment, -500},
      {ObservableId::pitch_moment, -501},
      {ObservableId::yaw_moment, -502},
      {ObservableId::climb_sp, 601},
      {ObservableId::vertical_p_term, -602},
      {ObservableId::vertical_integral, 603},
      {ObservableId::vertical_thrust, 2604},
  };
  for (const auto& [id, value] : expected)
    EXPECT_EQ(read_observable(flight, static_cast<uint8_t>(id)), value) << wire::kObservableTable[uint8_t(id)].name;
}

// A board whose cycle counter moves by a different amount at every read, so each task's last run
// measures differently from its neighbours'.
struct UnevenCyclesBoard : fake::FakeBoard {
  uint32_t reads = 0;
  uint32_t counter = 0;
  uint32_t cycles() {
    ++reads;
    counter += 10 + (reads * 7) % 31;
    return counter;
  }
};

// cycles_<task> is the scheduler's last measurement of that task, for every task row.
TEST(StreamTaskCycles, EachCyclesRowIsItsTasksLastRun) {
  UnevenCyclesBoard board;
  board.sensors.battery_mv = 12000;
  Firmware flight;
  Scheduler<UnevenCyclesBoard, Firmware> scheduler{board, flight};
  EXPECT_EQ(read_observable(flight, wire::kFirstTaskCyclesObservable), 0) << "nothing measured yet";
  for (int tick = 0; tick < 37; ++tick) {
    scheduler.tick();
    for (uint8_t task = 0; task < wire::kTaskCount; ++task) {
      const uint8_t id = static_cast<uint8_t>(wire::kFirstTaskCyclesObservable + task);
      EXPECT_EQ(read_observable(flight, id),
                static_cast<int32_t>(wire::saturate_u16(scheduler.stats().task[task].last)))
          << wire::kObservableTable[id].name << " at tick " << tick;
    }
  }
  const auto link = read_observable(flight, static_cast<uint8_t>(wire::ObservableId::cycles_link));
  const auto filter = read_observable(flight, static_cast<uint8_t>(wire::ObservableId::cycles_filter));
  EXPECT_GT(link, 0);
  EXPECT_GT(filter, 0);
  EXPECT_NE(link, filter) << "the board measures neighbours differently: a mixed-up row would show";
}

// Bidirectional DShot: the ESCs' eRPM answers reach a stream as RPM per engine (14 poles: a
// period of 428 us is 140 186 eRPM, 20 026 RPM; a stopped motor reads 0).
TEST_F(StreamFlightTest, EngineRpmStreamsFromTheEscAnswers) {
  using wire::ObservableId;
  const uint8_t s = request_stream(
      2, static_cast<uint16_t>(kControlHz / 50),
      {static_cast<uint8_t>(ObservableId::rpm_front), static_cast<uint8_t>(ObservableId::rpm_right),
       static_cast<uint8_t>(ObservableId::rpm_back), static_cast<uint8_t>(ObservableId::rpm_left)});
  run_ms(100);
  EXPECT_EQ(answer_to(s), wire::NackReason::none);
  for (uint32_t& raw : board.esc.raw) raw = drivers::encode_erpm_answer(drivers::erpm_period_code(428));
  board.esc.raw[1] = drivers::encode_erpm_answer(drivers::erpm_period_code(856));
  board.esc.raw[3] = drivers::encode_erpm_answer(drivers::kErpmStopped);
  board.esc.fresh = 0xF;
  run_ms(200);
  wire::SampleUnpacker unpacker;
  unpacker.start(4);
  std::vector<std::vector<uint16_t>> samples;
  for (const auto& frame : got<wire::ObservableSamples>()) {
    unpacker.unpack(frame, [&](const int16_t* v) {
      samples.push_back({static_cast<uint16_t>(v[0]), static_cast<uint16_t>(v[1]), static_cast<uint16_t>(v[2]),
                         static_cast<uint16_t>(v[3])});
    });
  }
  ASSERT_GE(samples.size(), 12u);
  EXPECT_EQ(samples.front(), (std::vector<uint16_t>{0, 0, 0, 0})) << "no answer yet: 0";
  EXPECT_EQ(samples.back(), (std::vector<uint16_t>{20026, 10013, 20026, 0}));
  EXPECT_EQ(unpacker.lost(), 0u);
}

// The largest uniform selection the rule accepts (four streams of four observables at the
// smallest divider it takes), run for three seconds beside control and telemetry: every sample
// must arrive and the line must keep up. Prints the figure.
TEST_F(StreamFlightTest, TheLargestAcceptedSelectionIsCarriedInFull) {
  uint16_t divider = 1;
  for (;; ++divider) {
    bool all = true;
    for (uint8_t s = 0; s < wire::kStreamCount && all; ++s) {
      const uint8_t r = request_stream(s, divider, {0, 3, 6, 9});
      run_ms(5);
      all = answer_to(r) == wire::NackReason::none;
    }
    if (all) break;
    received.clear();
  }
  received.clear();
  line_backlog_max = 0;
  run_ms(3000);
  std::vector<wire::SampleUnpacker> unpackers(wire::kStreamCount);
  for (auto& u : unpackers) u.start(4);
  uint32_t values = 0;
  for (const auto& frame : got<wire::ObservableSamples>())
    values += 4u * unpackers[frame.stream()].unpack(frame, [](const int16_t*) {});
  uint32_t lost = 0;
  for (const auto& u : unpackers) lost += u.lost();
  const double samples_per_s = values / 3.0;
  const uint32_t promised = wire::kStreamCount * wire::stream_samples_per_s(kControlHz, divider, 4);
  EXPECT_EQ(lost, 0u);
  EXPECT_EQ(flight.tx_dropped_frames(), 0u);
  EXPECT_LT(line_backlog_max, 300u) << "the line keeps up: its backlog stays within a few ticks";
  EXPECT_NEAR(samples_per_s, promised, promised * 0.02);
  EXPECT_GE(got<wire::TelemetryAttitude>().size(), 140u) << "telemetry still at 50 Hz";
  std::printf(
      "{\"observables\": {\"control_hz\": %u, \"telemetry_hz\": 50, \"control_uplink_hz\": 50, \"streams\": %u, "
      "\"per_stream\": 4, \"divider\": %u, \"samples_per_s\": %.0f, \"lost\": %u, \"line_backlog_max_bytes\": %zu, "
      "\"rule_room_bytes_per_s\": %u}}\n",
      kControlHz, wire::kStreamCount, divider, samples_per_s, lost, line_backlog_max,
      wire::stream_room_bytes_per_s(50));
}

}  // namespace
}  // namespace qr
