// The QR's tasks and which of them each mode runs, in data-flow order: link first (the pilot's
// messages), then sensors to engines, then the safety machine's last word, then telemetry.
#pragma once

#include <stdint.h>

#include <common/mode.hpp>
#include <qr/core/task.hpp>

namespace qr {

enum FlightTask : uint8_t {
  kLinkTask,
  kFilterTask,
  kCalibrationTask,
  kEstimatorTask,
  kAttitudeControlTask,
  kYawControlTask,
  kMixerTask,
  kManualMixerTask,
  kSafetyTask,
  kTelemetryTask,
  kLoggerTask,
  kFlightTaskCount,
};

namespace task_sets {
// The filter and estimator also run in safe and panic, so the pilot sees attitude on the bench
// and the filters are settled when a flight mode starts. The logger runs in every mode: a log
// covers the whole flight, panic included.
inline constexpr uint8_t kSafe[] = {kLinkTask, kFilterTask, kEstimatorTask, kSafetyTask, kTelemetryTask, kLoggerTask};
inline constexpr uint8_t kPanic[] = {kLinkTask, kFilterTask, kEstimatorTask, kSafetyTask, kTelemetryTask, kLoggerTask};
inline constexpr uint8_t kManual[] = {kLinkTask, kFilterTask, kEstimatorTask, kManualMixerTask, kSafetyTask, kTelemetryTask, kLoggerTask};
inline constexpr uint8_t kCalibration[] = {kLinkTask, kFilterTask, kCalibrationTask, kSafetyTask, kTelemetryTask, kLoggerTask};
inline constexpr uint8_t kYawControl[] = {kLinkTask, kFilterTask, kEstimatorTask, kYawControlTask, kMixerTask, kSafetyTask, kTelemetryTask, kLoggerTask};
inline constexpr uint8_t kFullControl[] = {kLinkTask, kFilterTask, kEstimatorTask, kAttitudeControlTask, kYawControlTask, kMixerTask, kSafetyTask, kTelemetryTask, kLoggerTask};

template <size_t N>
constexpr TaskSet set(const uint8_t (&ids)[N]) {
  return {ids, static_cast<uint8_t>(N)};
}
}  // namespace task_sets

// Indexed by wire::Mode.
inline constexpr TaskSet kFlightTaskSets[wire::kModeCount] = {
    task_sets::set(task_sets::kSafe),        task_sets::set(task_sets::kPanic),
    task_sets::set(task_sets::kManual),      task_sets::set(task_sets::kCalibration),
    task_sets::set(task_sets::kYawControl),  task_sets::set(task_sets::kFullControl),
};

}  // namespace qr
