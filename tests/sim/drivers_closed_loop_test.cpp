// The hobbyist's hardware in closed loop (docs/drivers.md): the host firmware flown through a
// radio (CRSF RC frames at 150 Hz, armed by the switch: qrsim --rc crsf) with its engines as
// bidirectional DShot frames to simulated ESCs (qrsim --esc dshot), judged on the simulator's
// truth by the scenarios' own bands. Each test prints its figures as the JSON line qrsim would.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <qr/boards/sim/sim_qr.hpp>
#include <qr/sim_runner/pilot.hpp>
#include <qr/sim_runner/scenario.hpp>
#include <sim/vehicle.hpp>

namespace {

qrsim::ScenarioResult fly(const std::string& name, bool radio, bool dshot) {
  qrsim::ScenarioScript script;
  std::string error;
  EXPECT_TRUE(qrsim::find_scenario(name, script, error)) << error;
  qrsim::RunOptions options;
  options.radio = radio;
  options.dshot = dshot;
  const qrsim::ScenarioResult result = qrsim::run_scenario(script, options);
  std::printf("%s\n", qrsim::to_json(result).c_str());
  return result;
}

void expect_bands_hold(const qrsim::ScenarioResult& r) {
  EXPECT_TRUE(r.error.empty()) << r.error;
  for (const qrsim::CheckResult& c : r.checks) EXPECT_TRUE(c.pass) << c.band << " (" << r.scenario << ")";
}

// The roll step's bands (rise, overshoot, settle) hold when the sticks come by radio and the
// engines go out as DShot: the path adds at most a radio frame's age (6.7 ms) to the sticks and
// nothing to the engines (throttle 47 + 2e reads back as e).
TEST(DriversClosedLoop, ARollStepFliesThroughCrsfAndDshot) {
  const qrsim::ScenarioResult r = fly("step-roll", true, true);
  expect_bands_hold(r);
  EXPECT_GT(r.figure("esc_frames"), 0);
  EXPECT_EQ(r.figure("esc_frames_rejected"), 0);
  // Who flies and the link as telemetry_radio says: the radio, up.
  const auto flags = static_cast<uint8_t>(r.figure("radio_flags"));
  EXPECT_EQ(flags & 0x03, 0x03);
  // The front engine's RPM from its ESC's eRPM answer, against the rotor's true speed: within the
  // answer's period resolution and the telemetry's age (a slow group, 1/6 of the telemetry rate).
  const double truth = r.figure("rpm_front_truth");
  ASSERT_GT(truth, 1000);
  EXPECT_NEAR(r.figure("rpm_front_reported"), truth, 0.03 * truth);
}

// The radio's link lost in hover: the link watchdog watches the pilot's link (the PC's frames keep
// coming), so the firmware panics and lands as in the cable-pulled scenario, on its bands.
TEST(DriversClosedLoop, TheRadiosLinkLossLandsLikeTheCables) {
  const qrsim::ScenarioResult r = fly("link-loss", true, false);
  expect_bands_hold(r);
  EXPECT_EQ(r.figure("entered_panic"), 1);
}

// A flying mode the radio's switches do not arm (height hold, acro: wire::armed_by_the_radio) is
// asked for on the PC link, as the console's key asks, and the QR refuses it while the radio flies
// (radio_is_pilot, docs/safety.md rule 17). The scenario pilot moved the radio's switches for any
// flying mode: for acro the mode switch went high and the radio armed full control, and for height
// hold the arm switch's off-and-on in flight was the emergency stop (a panic 0.5 s in).
TEST(DriversClosedLoop, AModeTheRadioDoesNotArmIsAskedOfTheQrAndRefused) {
  const qrsim::ScenarioResult height = fly("height-hold", true, false);
  EXPECT_TRUE(height.error.empty()) << height.error;
  EXPECT_EQ(height.figure("entered_panic"), 0) << "no emergency stop";
  EXPECT_EQ(height.final_mode, "full") << "refused: the radio's full control flies on";
  EXPECT_GE(height.figure("nacks"), 1);
  const qrsim::ScenarioResult acro = fly("acro-roll", true, false);
  EXPECT_TRUE(acro.error.empty()) << acro.error;
  EXPECT_EQ(acro.final_mode, "safe") << "refused, not armed as full control";
  EXPECT_GE(acro.figure("nacks"), 1);
}

// The same, the pilot's own view: the request's nack says why, and the radio's switches never
// moved (no arming, no emergency stop).
TEST(DriversClosedLoop, ThePilotsRequestForAcroIsNackedRadioIsPilot) {
  const std::unique_ptr<qrsim::SimQr> qr = qrsim::make_qr(sim::default_vehicle(), sim::WorldConfig{.seed = 1});
  qrsim::Pilot pilot(qr->board);
  const auto until = [&](double limit_s, const auto& done) {
    for (uint32_t i = 0; i < limit_s * qr::kControlHz && !done(); ++i) {
      pilot.step();
      qr->tick();
    }
    return done();
  };
  until(0.3, [] { return false; });
  pilot.set_parameter(wire::ParamId::pilot, 1);
  pilot.use_radio();
  pilot.request_mode(wire::Mode::calibration);
  ASSERT_TRUE(until(10, [&] {
    return (pilot.view().flags & wire::kFlagCalibrated) != 0 && qr->firmware.mode() == wire::Mode::safe &&
           !pilot.request_pending(wire::MessageType::mode_change) &&
           !pilot.request_pending(wire::MessageType::param_set);
  }));
  ASSERT_EQ(qr->firmware.pilot(), qr::Pilot::radio);
  pilot.request_mode(wire::Mode::acro);
  ASSERT_TRUE(until(2, [&] { return pilot.view().nacks > 0; }));
  EXPECT_EQ(pilot.view().last_nack, wire::NackReason::radio_is_pilot);
  until(0.5, [] { return false; });
  EXPECT_EQ(qr->firmware.mode(), wire::Mode::safe);
}

// The PC's link lost in hover with DShot ESCs: the panic sets the QR down and stops the engines,
// and then, in safe, the ESCs get the lost-model beacon (docs/safety.md rule 18), never while a
// motor turns. In hover before the loss (link alive, engines turning) none.
TEST(DriversClosedLoop, TheBeaconSoundsOnlyOnceTheEnginesStopped) {
  const qrsim::ScenarioResult hover = fly("hover", false, true);
  EXPECT_EQ(hover.figure("esc_commands"), 0);
  const qrsim::ScenarioResult r = fly("link-loss", false, true);
  expect_bands_hold(r);
  EXPECT_EQ(r.final_mode, "safe");
  EXPECT_GE(r.figure("esc_commands"), 4) << "a beacon frame to each of the four ESCs at least";
  EXPECT_EQ(r.figure("esc_commands_while_turning"), 0);
}

// Hover with the engines as DShot only (the PC flies).
TEST(DriversClosedLoop, HoverOnDshotEngines) {
  const qrsim::ScenarioResult r = fly("hover", false, true);
  expect_bands_hold(r);
  EXPECT_EQ(r.figure("esc_frames_rejected"), 0);
}

}  // namespace
