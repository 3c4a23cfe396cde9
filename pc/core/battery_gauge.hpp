// The battery as a pilot reads it (docs/console.md, the battery row): the charge left in per cent
// and the time left until the QR's battery panic, from what reaches the console: the voltage the
// QR measures (telemetry_system), the engines (telemetry_engines) and the parameters the console
// sends it. The charge is read from the resting voltage, as the QR's battery rules judge it
// (docs/safety.md rule 8: the measured voltage plus the sag the engines' load causes,
// battery_sag_mv, as a one-second mean), so a climb's sag does not read as a lost quarter of the
// pack, and the console and the QR agree on when the panic comes.
//
// Cells: counted from the first report after the link comes up (the highest a charged LiPo cell
// rests at, kHighestCellMv, into the voltage, rounded up), unless the pilot names them (--cells).
// A count is right for n cells while they rest above 4.25 V (n - 1) / n: any 3S pack above 2.9 V
// a cell, a 4S above 3.2 V; a deeper discharged pack of more cells needs --cells.
#pragma once

#include <stdint.h>

#include <deque>
#include <optional>
#include <string>

namespace qrterm {

inline constexpr double kRestingMeanS = 1.0;     // the QR's battery mean's time constant
inline constexpr double kChargeWindowS = 30.0;   // the charge's fall is measured over this
inline constexpr double kChargeMinSpanS = 10.0;  // ... once the reports span this much
inline constexpr double kChargeMinFall = 0.5;    // per cent: a fall beyond the voltage's noise
// The engines starting or stopping step the load, and the sag the QR's model misses steps the
// resting voltage with it: the fall is measured only from this long (three of the mean's time
// constants) after the last start or stop, so a take-off does not read as charge spent.
inline constexpr double kLoadSettleS = 3.0;
inline constexpr double kNearPanicPoints = 10.0;  // warn this close to the panic's charge
inline constexpr double kNearPanicS = 60.0;       // ... or this soon before it
inline constexpr int kHighestCellMv = 4250;       // a charged cell at rest, and a little more
inline constexpr int kMaxCells = 8;

// The charge of a LiPo cell resting at `cell_volts`, 0..100 %.
double lipo_charge_percent(double cell_volts);
// The cells of a pack resting at `resting_mv`, 1..kMaxCells.
int count_cells(uint16_t resting_mv);

// The charge at a moment (the console's seconds).
struct ChargeSample {
  double t_s;
  double percent;
};

struct BatteryReading {
  int cells = 0;
  double resting_v = 0;                // the mean the charge is read from
  double percent = 0;                  // 0..100
  double panic_percent = 0;            // the charge at the QR's panic threshold
  std::optional<double> seconds_left;  // until the panic threshold; empty until the fall is known
  bool near_panic = false;             // within kNearPanicPoints or kNearPanicS of the panic threshold
};

class BatteryGauge {
 public:
  // `cells`: the pack's, from --cells; 0: counted at connection.
  explicit BatteryGauge(int cells = 0) : given_cells_(cells) {}

  // The link came up: the QR may have another pack now; count its cells again.
  void link_up();
  // A telemetry_system report: the measured voltage, the engines as last reported and the
  // battery_sag_mv the console sent, at the console's time `now_s`.
  void on_report(uint16_t measured_mv, const uint16_t (&engines)[4], uint16_t sag_mv, double now_s);
  // Against the QR's panic threshold (battery_panic_mv); empty before the first report.
  std::optional<BatteryReading> reading(uint16_t panic_mv) const;
  // A line for the log once the charge comes near the panic (again after a fresh pack), else empty.
  std::string notice(uint16_t panic_mv);

 private:
  int given_cells_;
  int cells_ = 0;
  std::optional<double> mean_mv_;
  double last_s_ = 0;
  bool running_ = false;              // an engine turns (as last reported)
  double settled_s_ = 0;              // the charge's fall is measured from here on
  std::deque<ChargeSample> samples_;  // the charge over the last kChargeWindowS
  bool warned_ = false;
};

// "3S 84 % 7:30 left", "3S 84 % -- left".
std::string charge_text(const BatteryReading& reading);

}  // namespace qrterm
