// The QR's tasks as the wire numbers them (telemetry_task's `task` field, docs/protocol.md 5.2):
// number i is row i of the firmware's task table (qr/core/flight_tasks.hpp), which takes its
// names from here. The console shows the same names.
#pragma once

#include <stdint.h>

namespace wire {

inline constexpr const char* kTaskNames[] = {
    "link",     "filter", "calibration", "accel_angles", "estimator", "height", "attitude",
    "yaw",      "mixer",  "manual",      "safety",       "telemetry", "logger",
    "vertical",  // added after the others: the wire's numbers of the older tasks stay
    "stream",
};
inline constexpr uint8_t kTaskCount = sizeof(kTaskNames) / sizeof(kTaskNames[0]);

// "task N" for a number this table does not know (a newer firmware's).
constexpr const char* task_name(uint8_t task) { return task < kTaskCount ? kTaskNames[task] : nullptr; }

}  // namespace wire
