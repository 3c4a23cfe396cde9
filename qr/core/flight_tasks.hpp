// The tick in two tables: the tasks (one row each: name, what it runs, rate, phase, budget) and
// the modes (one row each: the tasks it runs, in data-flow order, and what entering it does).
// Link first (the pilot's messages), then sensors to engines, then the safety machine's last
// word, then telemetry and the logs. docs/architecture.md prints both tables.
//
// Both are templates over the context that runs them: qr::Flight in flight, and the replay's
// context (qr/core/replay_tick.hpp), which runs the same rows for its chain work so test
// mode runs the tick the flight runs.
#pragma once

#include <stdint.h>

#include <common/mode.hpp>
#include <common/task_names.hpp>
#include <qr/core/chain/engine_sources.hpp>
#include <qr/core/flight_types.hpp>
#include <qr/core/task.hpp>

namespace qr {

enum FlightTask : uint8_t {
  kLinkTask,
  kFilterTask,
  kCalibrationTask,
  kAccelAnglesTask,
  kEstimatorTask,
  kHeightTask,
  kAttitudeControlTask,
  kYawControlTask,
  kMixerTask,
  kManualMixerTask,
  kSafetyTask,
  kTelemetryTask,
  kLoggerTask,
  kVerticalTask,  // numbered after the older tasks (their wire numbers stay), runs after the height estimate
  kStreamTask,
  kFlightTaskCount,
};
static_assert(kFlightTaskCount == wire::kTaskCount, "one wire task number per row");

// Budgets are RV32IM instructions per run: the largest run `scripts/devboard --bench` measures in
// any mode, rounded up with 10-50 % room (the link's largest is a param_set in safe: its guard's
// bitwise CRC-24, about 600, and the parameter fan-out's divisions, 4002 with the landing's
// descent rate among the parameters; the estimator's its restart from the
// accelerometer, the safety machine's a mode announcement, the calibration's the run that
// finishes: offsets, the height reference's one division, and the sign probe's three mixes,
// about 1350, once per calibration: sign_check.hpp). The logger's is a line of both logs packed
// at 1 kHz with one order of a predictor's fit (the bench's full-log-1khz: 9847; log_pack/). The
// rv32 test Devboard.TaskBudgetsHold
// fails when a measured maximum exceeds its budget. Phases keep the divided tasks off each
// other's ticks: the accelerometer angles fall on ticks 0 mod 4, the height estimate and the
// vertical loops on 2 mod 4, telemetry and the logger on odd ones. The vertical task's largest
// run is a landing's (100).
template <class Flight>
inline constexpr Task<Flight> kFlightTaskTable[kFlightTaskCount] = {
    // name          run                                                   divider  phase  budget
    {wire::kTaskNames[kLinkTask], [](Flight& f) { f.run_link(); }, 1, 0, 5500},
    {wire::kTaskNames[kFilterTask], [](Flight& f) { f.run_filter(); }, 1, 0, 700},
    {wire::kTaskNames[kCalibrationTask], [](Flight& f) { f.run_calibration(); }, 1, 0, 1600},
    {wire::kTaskNames[kAccelAnglesTask], [](Flight& f) { f.chain().estimate_accel_angles(); },
     Flight::ChainType::kAccelDivider, 0, 1000},
    {wire::kTaskNames[kEstimatorTask], [](Flight& f) { f.chain().estimate(); }, 1, 0, 1500},
    {wire::kTaskNames[kHeightTask], [](Flight& f) { f.chain().estimate_height(); }, Flight::ChainType::kHeightDivider,
     Flight::ChainType::kHeightDivider / 2, 400},
    {wire::kTaskNames[kAttitudeControlTask], [](Flight& f) { f.chain().control_attitude(); }, 1, 0, 450},
    {wire::kTaskNames[kYawControlTask], [](Flight& f) { f.chain().control_yaw(); }, 1, 0, 140},
    {wire::kTaskNames[kMixerTask], [](Flight& f) { f.run_mixer(); }, 1, 0, 800},
    {wire::kTaskNames[kManualMixerTask], [](Flight& f) { f.run_manual_mixer(); }, 1, 0, 700},
    {wire::kTaskNames[kSafetyTask], [](Flight& f) { f.run_safety(); }, 1, 0, 1800},
    // Rates that are parameters: telemetry_rate_hz and log_divider.
    {wire::kTaskNames[kTelemetryTask], [](Flight& f) { f.run_telemetry(); }, 1, 1, 2000,
     [](const Flight& f) { return f.telemetry_divider(); }},
    {wire::kTaskNames[kLoggerTask], [](Flight& f) { f.run_logger(); }, 1, 3, 12000,
     [](const Flight& f) { return f.log_divider(); }},
    // On the height estimate's ticks, after it: each run sees a fresh height and vertical speed.
    {wire::kTaskNames[kVerticalTask], [](Flight& f) { f.chain().control_vertical(); },
     Flight::ChainType::kHeightDivider, Flight::ChainType::kHeightDivider / 2, 200},
    // Every tick: each observable stream samples on its own divider, the request's (data, not
    // code: observable_streams.hpp); idle it only checks four slots. The bench's largest run (1228)
    // is a sample of two streams and a frame of the observable table on one tick.
    {wire::kTaskNames[kStreamTask], [](Flight& f) { f.run_stream(); }, 1, 0, 1400},
};

// The table as a pointer (for readers, cppcheck among them, that stumble on a variable template
// indexed in place).
template <class Flight>
constexpr const Task<Flight>* flight_tasks() {
  return kFlightTaskTable<Flight>;
}

// Row i is task i: its name is wire::kTaskNames[i], the number telemetry_task reports.
template <class Flight>
constexpr bool rows_in_task_order() {
  for (uint8_t i = 0; i < kFlightTaskCount; ++i) {
    if (flight_tasks<Flight>()[i].name != wire::kTaskNames[i]) return false;
  }
  return true;
}

namespace task_sets {
// The filter and estimators also run in safe and panic, so the pilot sees attitude and height on
// the bench and the filters are settled when a flight mode starts. The logger runs in every mode: a log
// covers the whole flight, panic included.
inline constexpr uint8_t kSafe[] = {kLinkTask,   kFilterTask, kAccelAnglesTask, kEstimatorTask, kHeightTask,
                                    kSafetyTask, kStreamTask, kTelemetryTask,   kLoggerTask};
// A panic runs the control tasks: a landing flies on them (the safety machine passes their
// engines); the cut (hold, ramp) overrides them.
inline constexpr uint8_t kPanic[] = {kLinkTask,     kFilterTask,          kAccelAnglesTask, kEstimatorTask, kHeightTask,
                                     kVerticalTask, kAttitudeControlTask, kYawControlTask,  kMixerTask,     kSafetyTask,
                                     kStreamTask,   kTelemetryTask,       kLoggerTask};
inline constexpr uint8_t kManual[] = {kLinkTask,        kFilterTask, kAccelAnglesTask, kEstimatorTask, kHeightTask,
                                      kManualMixerTask, kSafetyTask, kStreamTask,      kTelemetryTask, kLoggerTask};
inline constexpr uint8_t kCalibration[] = {kLinkTask,   kFilterTask,    kCalibrationTask, kSafetyTask,
                                           kStreamTask, kTelemetryTask, kLoggerTask};
// Yaw control, full control, height hold, acro and panic fly the same rows, so they share one set
// (the scheduler compiles each set into code of its own, and the image has to stay within the
// board's budget, docs/devboard.md); the mode's sources (kFlightModes) say which rows' outputs fly:
// in yaw control the attitude task runs but the sticks fly roll and pitch (its moments are fresh
// for a panic's landing entered from there, in the tick the panic comes), in full control the
// vertical task returns at once (the lift is the pilot's); in height hold it flies the lift; a
// panic that lands flies its descent on all of them, and the cut (hold, ramp) overrides their
// engines.
inline constexpr uint8_t kFlying[] = {
    kLinkTask,       kFilterTask, kAccelAnglesTask, kEstimatorTask, kHeightTask,    kVerticalTask, kAttitudeControlTask,
    kYawControlTask, kMixerTask,  kSafetyTask,      kStreamTask,    kTelemetryTask, kLoggerTask};

template <size_t N>
constexpr TaskSet set(const uint8_t (&ids)[N]) {
  return {ids, static_cast<uint8_t>(N)};
}
}  // namespace task_sets

// A mode as the QR runs it: its tasks, where each part of the engines' command comes from
// (engine_sources.hpp: the mixer reads it, nothing else decides), and its entry action, run once
// by the transition into it and told the mode it came from (nullptr: nothing to do). The mode's
// other facts are the shared table's (common/mode.hpp). Adding a mode is a row here and one there
// (docs/architecture.md, "How to add ...": acro was added so).
template <class Flight>
struct FlightMode {
  Mode mode;
  TaskSet tasks;
  chain::EngineSources sources;
  void (*enter)(Flight&, Mode from);
};

namespace sources {
using chain::Lift;
using chain::Tilt;
using chain::Yaw;
inline constexpr chain::EngineSources kYawControl{Tilt::stick, Yaw::rate, Lift::stick};
inline constexpr chain::EngineSources kFullControl{Tilt::angle, Yaw::rate, Lift::stick};
inline constexpr chain::EngineSources kHeightHold{Tilt::angle, Yaw::rate, Lift::hold};
inline constexpr chain::EngineSources kAcro{Tilt::rate, Yaw::rate, Lift::stick};
inline constexpr chain::EngineSources kAutotune{Tilt::angle, Yaw::rate, Lift::stick, chain::Excite::prbs};
// A panic's cut: the loops fly the pilot's angles on the pilot's lift, as they did, while the
// safety machine's hold and ramp override the engines; a panic that lands flies chain::kLanding.
inline constexpr chain::EngineSources kCut = kFullControl;
}  // namespace sources

template <class Flight>
inline constexpr FlightMode<Flight> kFlightModes[kModeCount] = {
    {Mode::safe, task_sets::set(task_sets::kSafe), chain::kOpenLoop, nullptr},
    // A panic lands (the safety machine says which panic it is) from the lift that was flying, or
    // cuts (Flight::enter_panic).
    {Mode::panic, task_sets::set(task_sets::kFlying), chain::kLanding, [](Flight& f, Mode) { f.enter_panic(); }},
    {Mode::manual, task_sets::set(task_sets::kManual), chain::kOpenLoop, nullptr},
    // A calibration run starts over whenever the mode is entered.
    {Mode::calibration, task_sets::set(task_sets::kCalibration), chain::kOpenLoop,
     [](Flight& f, Mode) { f.chain().enter_calibration(); }},
    // The yaw loop's integral starts empty.
    {Mode::yaw_control, task_sets::set(task_sets::kFlying), sources::kYawControl,
     [](Flight& f, Mode) { f.chain().enter_yaw_control(); }},
    // The attitude and yaw loops' integrals start empty, unless the vehicle comes back from height
    // hold or the autotune: it flew on, and the integrals hold its trim.
    {Mode::full_control, task_sets::set(task_sets::kFlying), sources::kFullControl,
     [](Flight& f, Mode from) {
       if (wire::entered_in_flight(from)) return;
       f.chain().enter_attitude_control();
       f.chain().enter_yaw_control();
     }},
    // The height at entry is held from the thrust the pilot's lift gave.
    {Mode::height_hold, task_sets::set(task_sets::kFlying), sources::kHeightHold,
     [](Flight& f, Mode) { f.chain().enter_height_hold(); }},
    // The rate loops alone, their integrals empty.
    {Mode::acro, task_sets::set(task_sets::kFlying), sources::kAcro,
     [](Flight& f, Mode) {
       f.chain().enter_attitude_control();
       f.chain().enter_yaw_control();
     }},
    // Safe's rows: no mixer runs; the safety machine gives the one engine its level.
    {Mode::motor_test, task_sets::set(task_sets::kSafe), chain::kOpenLoop, nullptr},
    // Full control's loops, their integrals as they were, and the identification's sequence from
    // its start.
    {Mode::autotune, task_sets::set(task_sets::kFlying), sources::kAutotune,
     [](Flight& f, Mode) { f.chain().enter_identification(); }},
};

// The distinct sets, each compiled once, and which of them each mode runs (modes_in_order and the
// flight's static checks keep the two tables in step).
inline constexpr TaskSet kCompiledSets[] = {
    task_sets::set(task_sets::kSafe),
    task_sets::set(task_sets::kManual),
    task_sets::set(task_sets::kCalibration),
    task_sets::set(task_sets::kFlying),
};
inline constexpr uint8_t kCompiledSetCount = sizeof(kCompiledSets) / sizeof(kCompiledSets[0]);

// The compiled set a mode's row names (the same rows are the same set).
template <class Flight>
constexpr uint8_t compiled_set_of(uint8_t mode);

// The mode table as a pointer, as flight_tasks() above.
template <class Flight>
constexpr const FlightMode<Flight>* flight_modes() {
  return kFlightModes<Flight>;
}

template <class Flight>
constexpr uint8_t compiled_set_of(uint8_t mode) {
  for (uint8_t s = 0; s < kCompiledSetCount; ++s) {
    if (kCompiledSets[s].ids == flight_modes<Flight>()[mode].tasks.ids) return s;
  }
  return kCompiledSetCount;  // not compiled: every_mode_has_a_compiled_set() fails
}

template <class Flight>
constexpr bool every_mode_has_a_compiled_set() {
  for (uint8_t m = 0; m < kModeCount; ++m) {
    if (compiled_set_of<Flight>(m) >= kCompiledSetCount) return false;
  }
  return true;
}

// Every loop a mode's sources name runs in the mode's set, so the mixer reads this tick's moments
// and the vertical loops' thrust; and the manual set's mixer, which mixes the sticks whatever the
// sources, serves only modes flown open loop.
constexpr bool set_has(TaskSet set, uint8_t task) {
  for (uint8_t i = 0; i < set.count; ++i) {
    if (set.ids[i] == task) return true;
  }
  return false;
}
template <class Flight>
constexpr bool sources_have_their_tasks() {
  for (uint8_t m = 0; m < kModeCount; ++m) {
    const FlightMode<Flight>& row = flight_modes<Flight>()[m];
    const chain::EngineSources& s = row.sources;
    if (!set_has(row.tasks, kMixerTask) && !set_has(row.tasks, kManualMixerTask)) continue;  // engines zero
    if (s.tilt != chain::Tilt::stick && !set_has(row.tasks, kAttitudeControlTask)) return false;
    if (s.yaw != chain::Yaw::stick && !set_has(row.tasks, kYawControlTask)) return false;
    if (s.lift != chain::Lift::stick && !set_has(row.tasks, kVerticalTask)) return false;
    const bool open_loop = s.tilt == chain::Tilt::stick && s.yaw == chain::Yaw::stick && s.lift == chain::Lift::stick;
    if (set_has(row.tasks, kManualMixerTask) && !open_loop) return false;
  }
  return true;
}

template <class Flight>
constexpr bool modes_in_order() {
  for (uint8_t i = 0; i < kModeCount; ++i) {
    if (index(flight_modes<Flight>()[i].mode) != i) return false;
  }
  return true;
}

}  // namespace qr
