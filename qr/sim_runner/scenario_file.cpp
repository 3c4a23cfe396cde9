// The scenario file format (docs/simulator.md): one statement a line, `#` starts a comment.
//   keyword: value          a setting (summary, seconds, start, vehicle, mass, ...)
//   at T action values...   an event, T seconds after t0, in time order
//   band figure op limit    a pass band, op one of <, <=, ==, >, >=
// Every error names the file and the line, so a user finds the mistake without the source.
#include <qr/sim_runner/scenario_script.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

#include <common/drivers/mpu6050.hpp>
#include <common/drivers/ms5611.hpp>
#include <qr/sim_runner/scenario_figures.hpp>
#include <qr/sim_runner/text_fields.hpp>

namespace qrsim {
namespace {

std::string joined(const std::vector<std::string>& words, size_t from) {
  std::string out;
  for (size_t i = from; i < words.size(); ++i) out += (i == from ? "" : " ") + words[i];
  return out;
}

std::string text_of(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

bool mode_from_key(const std::string& key, wire::Mode& mode) {
  for (const wire::ModeSpec& m : wire::kModeTable) {
    if (key == m.key) {
      mode = m.mode;
      return true;
    }
  }
  return false;
}

std::string mode_keys() {
  std::string out;
  for (const wire::ModeSpec& m : wire::kModeTable) out += (out.empty() ? "" : ", ") + std::string(m.key);
  return out;
}

class Reader;

// An event's action word and the Reader's parser for the rest of its line.
struct EventKeyword {
  const char* action;
  bool (Reader::*parse)(const std::vector<std::string>& w, Event& e);
};

// Reads one file's statements into a script; the first problem ends the reading.
class Reader {
 public:
  Reader(const std::string& origin, ScenarioScript& out) : origin_(origin), out_(out) {}

  bool line(int number, const std::string& raw) {
    line_ = number;
    const std::string text = raw.substr(0, raw.find('#'));
    const std::vector<std::string> w = words_of(text);
    if (w.empty()) return true;
    if (w[0] == "at") return event(w);
    if (w[0] == "band") return band(w);
    if (w[0].size() > 1 && w[0].back() == ':') return setting(w[0].substr(0, w[0].size() - 1), w);
    return fail("unknown keyword '" + w[0] + "' (a setting 'name: value', 'at T ...' or 'band ...')");
  }

  bool finish() {
    line_ = 0;
    if (!seen("seconds")) return fail("no 'seconds:' line: the scored window must be given");
    if (out_.bands.empty()) return fail("no band: a scenario must say what it is judged by");
    for (const Event& e : out_.events) {
      if (e.at_s >= out_.seconds) {
        line_ = e.line;
        return fail("event at " + std::to_string(e.at_s) +
                    " s is past the window (seconds: " + std::to_string(out_.seconds) + ")");
      }
    }
    return true;
  }

  const std::string& error() const { return error_; }

 private:
  bool fail(const std::string& what) {
    error_ = origin_ + (line_ > 0 ? ":" + std::to_string(line_) : "") + ": " + what;
    return false;
  }

  bool get_number(const std::string& text, double& out, const char* what) {
    if (parse_real(text, out)) return true;
    return fail(std::string("bad number '") + text + "' for " + what);
  }

  bool seen(const std::string& key) const {
    for (const std::string& s : seen_) {
      if (s == key) return true;
    }
    return false;
  }

  bool setting(const std::string& key, const std::vector<std::string>& w) {
    // A flight may need several parameters changed: param: is the one setting that repeats.
    if (key == "param") return parameter_line(w);
    if (seen(key)) return fail("'" + key + ":' given twice");
    seen_.push_back(key);
    const std::string value = joined(w, 1);
    if (key == "summary") {
      out_.summary = value;
      return true;
    }
    if (key == "known_failure") {
      if (value.empty()) return fail("known_failure: needs its reason");
      out_.known_failure = value;
      return true;
    }
    if (sim::is_wiring_name(key)) {
      std::string problem;
      if (!sim::parse_wiring_row(key, value, out_.wiring, problem)) return fail(problem);
      return true;
    }
    if (key == "vehicle") {
      if (w.size() != 2) return fail("vehicle: needs one file name");
      out_.vehicle_file = value;
      out_.vehicle_line = line_;
      return true;
    }
    if (key == "start") {
      if (value == "hover") {
        out_.start = Start::hover;
      } else if (value == "ground") {
        out_.start = Start::ground;
      } else if (value == "safe") {
        out_.start = Start::safe;
      } else {
        return fail("start: is 'hover', 'ground' or 'safe', not '" + value + "'");
      }
      return true;
    }
    struct Number {
      const char* key;
      double* field;
      double min, max;  // accepted, inclusive
    };
    const Number numbers[] = {
        {"seconds", &out_.seconds, 0.01, 3600},       {"mass", &out_.mass_scale, 0.1, 10},
        {"inertia", &out_.inertia_scale, 0.1, 10},    {"motor_tau_ms", &out_.motor_tau_ms, 1, 1000},
        {"battery_pct", &out_.battery_pct, 0, 100},   {"noise", &out_.noise_scale, 0, 100},
        {"vibration", &out_.vibration_scale, 0, 100},
    };
    for (const Number& n : numbers) {
      if (key != n.key) continue;
      if (w.size() != 2) return fail(key + ": needs one number");
      double v = 0;
      if (!get_number(w[1], v, n.key)) return false;
      if (v < n.min || v > n.max) {
        std::ostringstream range;
        range << key << ": " << v << " is outside " << n.min << " .. " << n.max;
        return fail(range.str());
      }
      *n.field = v;
      return true;
    }
    return fail("unknown setting '" + key + ":'");
  }

  // param: NAME VALUE, uploaded in the file's order. The same parameter twice is a mistake, not
  // an override: which of the two values the user meant cannot be told.
  bool parameter_line(const std::vector<std::string>& w) {
    if (w.size() != 3) return fail("param: needs NAME VALUE");
    wire::ParamId id{};
    int32_t raw = 0;
    const std::string problem = parameter_from_text(w[1], w[2], id, raw);
    if (!problem.empty()) return fail(problem);
    for (const auto& [earlier, line] : parameter_lines_) {
      if (earlier == id) return fail("param: " + w[1] + " given twice (first on line " + std::to_string(line) + ")");
    }
    parameter_lines_.emplace_back(id, line_);
    out_.parameters.emplace_back(id, raw);
    return true;
  }

  bool vector_for(const std::vector<std::string>& w, Event& e, const char* unit) {
    // at T torque X Y Z for S  /  at T force N E D for S  /  at T wind N E D
    const bool lasting = e.action != Action::wind;
    const size_t want = lasting ? 8 : 6;
    if (w.size() != want || (lasting && w[6] != "for")) {
      return fail(w[2] + (lasting ? " needs X Y Z for SECONDS (" : " needs N E D (") + unit + ")");
    }
    if (!get_number(w[3], e.vector.x, unit) || !get_number(w[4], e.vector.y, unit) ||
        !get_number(w[5], e.vector.z, unit)) {
      return false;
    }
    // Far beyond what the vehicle can take (its weight is 10 N; 1 N m tips it past 45 deg).
    const double limit = e.action == Action::torque ? 10 : e.action == Action::force ? 100 : 50;
    if (std::abs(e.vector.x) > limit || std::abs(e.vector.y) > limit || std::abs(e.vector.z) > limit) {
      return fail(w[2] + " is beyond +-" + text_of(limit) + " (" + unit + ") on an axis");
    }
    if (lasting) {
      if (!get_number(w[7], e.duration_s, "the duration")) return false;
      if (e.duration_s <= 0) return fail("the duration must be > 0");
    }
    return true;
  }

  // at T turn AXIS N for S: N whole turns about body axis AXIS in S seconds, one turn at a time.
  bool turn(const std::vector<std::string>& w, Event& e) {
    e.action = Action::turn;
    if (w.size() != 7 || w[5] != "for") return fail("turn needs AXIS N for SECONDS (AXIS x, y or z; N whole turns)");
    if (!sim::body_axis_from_text(w[3], e.turn.axis)) return fail("turn axis is x, y or z, not '" + w[3] + "'");
    double turns = 0;
    if (!get_number(w[4], turns, "the turns") || !get_number(w[6], e.turn.seconds, "the turn's seconds")) return false;
    e.turn.turns = sim::whole_turns(turns);
    e.value = e.turn.turns;
    e.duration_s = e.turn.seconds;
    const std::string problem = sim::hand_turn_problem(e.turn);
    if (!problem.empty()) return fail("turn: " + problem);
    if (e.at_s < turn_until_) {
      std::ostringstream overlap;
      overlap << "turn at " << e.at_s << " s starts while the turn of line " << turn_line_ << " still acts (until "
              << turn_until_ << " s)";
      return fail(overlap.str());
    }
    turn_until_ = e.at_s + e.turn.seconds;
    turn_line_ = line_;
    return true;
  }

  // at T ACTION ...: the time is checked here, the rest by the action's parser (kEventKeywords).
  bool event(const std::vector<std::string>& w);
  static const EventKeyword kEventKeywords[];
  static std::string event_actions();

  // Limits keep a user's typo from feeding the plant numbers it cannot integrate.
  bool one_number(const std::vector<std::string>& w, Event& e, Action kind, const char* what, double limit) {
    e.action = kind;
    if (w.size() != 4) return fail(w[2] + " needs one number (" + what + ")");
    if (!get_number(w[3], e.value, what)) return false;
    return std::abs(e.value) <= limit || fail(w[2] + " " + w[3] + " is beyond +-" + text_of(limit) + " " + what);
  }

  // A switch between two words: value 1 for the first, 0 for the second.
  bool either(const std::vector<std::string>& w, Event& e, Action kind, const char* one, const char* zero,
              const char* problem) {
    e.action = kind;
    if (w.size() != 4 || (w[3] != one && w[3] != zero)) return fail(problem);
    e.value = w[3] == one ? 1 : 0;
    return true;
  }

  bool roll(const std::vector<std::string>& w, Event& e) { return one_number(w, e, Action::roll, "degrees", 90); }
  bool pitch(const std::vector<std::string>& w, Event& e) { return one_number(w, e, Action::pitch, "degrees", 90); }
  bool yaw(const std::vector<std::string>& w, Event& e) { return one_number(w, e, Action::yaw, "rad/s", 20); }

  // at T lift hold|still|height METRES|SHARE
  bool lift(const std::vector<std::string>& w, Event& e) {
    lift_still_ = false;  // any lift event moves the hand, but `lift still`
    if (w.size() == 4 && w[3] == "hold") {
      e.action = Action::lift_hold;
      return true;
    }
    if (w.size() == 4 && w[3] == "still") {
      e.action = Action::lift_still;
      lift_still_ = true;
      return true;
    }
    if (w.size() == 5 && w[3] == "height") {
      e.action = Action::lift_height;
      if (!get_number(w[4], e.value, "the height")) return false;
      if (e.value < 0.2 || e.value > 100) return fail("lift height must be 0.2 .. 100 m");
      return true;
    }
    if (w.size() == 4) {
      e.action = Action::lift_share;
      if (!get_number(w[3], e.value, "the share of hover lift")) return false;
      if (e.value < 0 || e.value > 3) return fail("lift share must be 0 .. 3 (of the hover lift)");
      return true;
    }
    return fail("lift needs 'hold', 'height METRES', 'still' or a share of the hover lift");
  }

  bool mode(const std::vector<std::string>& w, Event& e) {
    e.action = Action::mode;
    if (w.size() != 4) return fail("mode needs one mode key (" + mode_keys() + ")");
    if (!mode_from_key(w[3], e.mode)) return fail("unknown mode '" + w[3] + "' (" + mode_keys() + ")");
    // The firmware leaves height hold and the autotune as soon as the lift stick moves
    // (SafetyMachine::sticks_moved), and the pilot's hand moves it every period unless told to
    // stop: the mode would last a few hundredths of a second with no word of why.
    if (wire::entered_in_flight(e.mode) && !lift_still_) {
      return fail("mode " + w[3] + " with the pilot's lift hand moving: " + wire::mode_name(e.mode) +
                  " ends at the lift stick's first change; add 'at T lift still' before it");
    }
    return true;
  }

  bool param(const std::vector<std::string>& w, Event& e) {
    e.action = Action::param;
    if (w.size() != 5) return fail("param needs NAME VALUE");
    const std::string problem = parameter_from_text(w[3], w[4], e.param, e.raw);
    return problem.empty() || fail(problem);
  }

  bool torque(const std::vector<std::string>& w, Event& e) {
    e.action = Action::torque;
    return vector_for(w, e, "N m, body axes");
  }

  bool force(const std::vector<std::string>& w, Event& e) {
    e.action = Action::force;
    return vector_for(w, e, "N, world axes");
  }

  bool wind(const std::vector<std::string>& w, Event& e) {
    e.action = Action::wind;
    return vector_for(w, e, "m/s, world axes");
  }

  bool link(const std::vector<std::string>& w, Event& e) {
    return either(w, e, Action::link, "on", "off", "link is 'on' or 'off'");
  }

  bool console(const std::vector<std::string>& w, Event& e) {
    return either(w, e, Action::console, "full", "normal", "console is 'full' (the line's full rate) or 'normal'");
  }

  // at T log start|stop|download sensor|telemetry
  bool log(const std::vector<std::string>& w, Event& e) {
    if (w.size() == 4 && w[3] == "start") {
      e.action = Action::log_start;
      return true;
    }
    if (w.size() == 4 && w[3] == "stop") {
      e.action = Action::log_stop;
      return true;
    }
    if (w.size() == 5 && w[3] == "download" && (w[4] == "sensor" || w[4] == "telemetry")) {
      e.action = Action::download;
      e.value = w[4] == "sensor" ? 0 : 1;
      return true;
    }
    return fail("log is 'start', 'stop' or 'download sensor|telemetry'");
  }

  // ---- faults on the sensors' bus and chips ----

  // at T nack imu|baro for S: the chip's address NACKs for S seconds.
  bool nack(const std::vector<std::string>& w, Event& e) {
    e.action = Action::nack;
    if (w.size() != 6 || w[4] != "for" || (w[3] != "imu" && w[3] != "baro")) {
      return fail("nack needs imu|baro for SECONDS");
    }
    e.value = w[3] == "imu" ? drivers::mpu6050::kAddressAd0Low : drivers::kMs5611AddressCsbLow;
    return fault_duration(w[5], e);
  }

  // at T sda stuck [for S]: the bus answers bus_stuck for S seconds, or for ever.
  bool sda(const std::vector<std::string>& w, Event& e) {
    e.action = Action::sda_stuck;
    if (w.size() == 4 && w[3] == "stuck") {
      e.duration_s = std::numeric_limits<double>::infinity();
      return true;
    }
    if (w.size() != 6 || w[3] != "stuck" || w[4] != "for") return fail("sda needs 'stuck' or 'stuck for SECONDS'");
    return fault_duration(w[5], e);
  }

  // at T imu identity BYTE / at T imu fifo overflow / at 0 imu selftest bad
  bool imu(const std::vector<std::string>& w, Event& e) {
    if (w.size() == 5 && w[3] == "fifo" && w[4] == "overflow") {
      e.action = Action::fifo_overflow;
      return true;
    }
    if (w.size() == 5 && w[3] == "selftest" && w[4] == "bad") {
      e.action = Action::imu_self_test;
      // The driver self-tests at power-up only: a part that fails is so from then, or never.
      return e.at_s == 0 || fail(
                                "imu selftest bad is the part's from power-up (the driver self-tests then only): "
                                "write it at 0");
    }
    if (w.size() != 5 || w[3] != "identity") {
      return fail("imu needs 'identity BYTE', 'fifo overflow' or 'selftest bad'");
    }
    e.action = Action::imu_identity;
    char* end = nullptr;
    const unsigned long v = std::strtoul(w[4].c_str(), &end, 0);
    if (w[4].empty() || *end != '\0' || v > 0xFF) {
      return fail("imu identity is a byte (0 .. 255 or 0x00 .. 0xff), not '" + w[4] + "'");
    }
    if (v == drivers::mpu6050::kIdentity) {
      return fail("imu identity 0x68 is the MPU-6050's own: a wrong one is any other");
    }
    e.value = static_cast<double>(v);
    return true;
  }

  // at T baro prom bad / at T baro slow MS for S
  bool baro(const std::vector<std::string>& w, Event& e) {
    if (w.size() == 5 && w[3] == "prom" && w[4] == "bad") {
      e.action = Action::prom_bad;
      return true;
    }
    if (w.size() != 7 || w[3] != "slow" || w[5] != "for") return fail("baro needs 'prom bad' or 'slow MS for SECONDS'");
    e.action = Action::baro_slow;
    if (!get_number(w[4], e.value, "the milliseconds of the slow conversion")) return false;
    if (e.value <= 0 || e.value > 100) return fail("baro slow must be > 0 and at most 100 ms");
    return fault_duration(w[6], e);
  }

  bool fault_duration(const std::string& text, Event& e) {
    if (!get_number(text, e.duration_s, "the duration")) return false;
    return (e.duration_s > 0 && e.duration_s <= 3600) || fail("the duration must be > 0 and at most 3600 s");
  }

  bool band(const std::vector<std::string>& w) {
    if (w.size() != 4) return fail("a band is 'band FIGURE OP LIMIT'");
    Band b;
    b.line = line_;
    b.figure = w[1];
    if (!is_figure(b.figure)) return fail("unknown band figure '" + b.figure + "' (docs/simulator.md lists them)");
    bool known = false;
    for (const Compare c : {Compare::below, Compare::at_most, Compare::equal, Compare::above, Compare::at_least}) {
      if (w[2] != compare_text(c)) continue;
      b.compare = c;
      known = true;
    }
    if (!known) return fail("unknown comparison '" + w[2] + "' (<, <=, ==, > or >=)");
    if (b.figure == "final_mode") {
      if (b.compare != Compare::equal) return fail("final_mode is compared with ==");
      wire::Mode mode{};
      if (!mode_from_key(w[3], mode)) return fail("unknown mode '" + w[3] + "' (" + mode_keys() + ")");
      b.limit = static_cast<double>(mode);
    } else if (!get_number(w[3], b.limit, "the band's limit")) {
      return false;
    }
    out_.bands.push_back(b);
    return true;
  }

  std::string origin_;
  ScenarioScript& out_;
  int line_ = 0;
  std::vector<std::string> seen_;
  std::vector<std::pair<wire::ParamId, int>> parameter_lines_;  // each param: line's parameter and line
  std::string error_;
  double turn_until_ = 0;    // when the last turn event ends, after t0
  bool lift_still_ = false;  // the last lift event was `lift still`: the stick stays put
  int turn_line_ = 0;
};

// The order is the unknown-action message's.
const EventKeyword Reader::kEventKeywords[] = {
    {"roll", &Reader::roll}, {"pitch", &Reader::pitch}, {"yaw", &Reader::yaw},       {"lift", &Reader::lift},
    {"mode", &Reader::mode}, {"param", &Reader::param}, {"torque", &Reader::torque}, {"force", &Reader::force},
    {"wind", &Reader::wind}, {"turn", &Reader::turn},   {"link", &Reader::link},     {"console", &Reader::console},
    {"log", &Reader::log},   {"nack", &Reader::nack},   {"sda", &Reader::sda},       {"imu", &Reader::imu},
    {"baro", &Reader::baro},
};

std::string Reader::event_actions() {
  std::string out;
  for (const EventKeyword& k : kEventKeywords) out += (out.empty() ? "" : ", ") + std::string(k.action);
  return out;
}

bool Reader::event(const std::vector<std::string>& w) {
  if (w.size() < 3) return fail("an event is 'at T action ...'");
  Event e;
  e.line = line_;
  if (!get_number(w[1], e.at_s, "the event's time")) return false;
  if (e.at_s < 0) return fail("event time must be >= 0");
  if (!out_.events.empty() && e.at_s < out_.events.back().at_s) {
    std::ostringstream order;
    order << "event out of order: at " << e.at_s << " after an event at " << out_.events.back().at_s;
    return fail(order.str());
  }
  for (const EventKeyword& k : kEventKeywords) {
    if (w[2] != k.action) continue;
    if (!(this->*k.parse)(w, e)) return false;
    out_.events.push_back(e);
    return true;
  }
  return fail("unknown action '" + w[2] + "' (" + event_actions() + ")");
}

}  // namespace

std::string parameter_from_text(const std::string& name, const std::string& value, wire::ParamId& id, int32_t& raw) {
  const std::string problem = qr::host::parameter_from_text(name, value, id, raw);
  if (problem.empty()) return problem;
  // Only a known name with a good number fails on its range; the other problems stand as they are.
  double real = 0;
  if (!parse_real(value, real)) return problem;
  for (const wire::ParameterSpec& s : wire::kParameterTable) {
    if (name != s.name) continue;
    // The range in the unit the value is written in: raw / 2^frac_bits.
    std::ostringstream range;
    range << std::setprecision(10) << "parameter " << name << ": " << value << " is out of its range "
          << std::ldexp(s.min, -s.frac_bits) << " .. " << std::ldexp(s.max, -s.frac_bits) << " (" << s.unit << ")";
    return range.str();
  }
  return problem;
}

const char* compare_text(Compare compare) {
  switch (compare) {
    case Compare::below: return "<";
    case Compare::at_most: return "<=";
    case Compare::equal: return "==";
    case Compare::above: return ">";
    case Compare::at_least: return ">=";
  }
  return "?";
}

std::string band_text(const Band& band) {
  char limit[32];
  if (band.figure == "final_mode") {
    std::snprintf(limit, sizeof limit, "%s", wire::mode_key(static_cast<wire::Mode>(band.limit)));
  } else {
    std::snprintf(limit, sizeof limit, "%g", band.limit);
  }
  return band.figure + " " + compare_text(band.compare) + " " + limit;
}

bool parse_scenario(const std::string& text, const std::string& name, const std::string& origin, ScenarioScript& out,
                    std::string& error) {
  out = ScenarioScript{};
  out.name = name;
  out.origin = origin;
  Reader reader(origin, out);
  std::istringstream in(text);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    if (!reader.line(++number, line)) {
      error = reader.error();
      return false;
    }
  }
  if (!reader.finish()) {
    error = reader.error();
    return false;
  }
  return true;
}

bool load_scenario_file(const std::string& path, ScenarioScript& out, std::string& error) {
  namespace fs = std::filesystem;
  std::ifstream in(path);
  if (!in) {
    error = path + ": cannot read";
    return false;
  }
  std::stringstream text;
  text << in.rdbuf();
  if (!parse_scenario(text.str(), fs::path(path).stem().string(), path, out, error)) return false;
  if (!out.vehicle_file.empty()) {
    const fs::path vehicle = fs::path(path).parent_path() / out.vehicle_file;
    sim::VehicleParams v;
    std::string why;
    if (!sim::load_vehicle_file(vehicle.string(), v, why)) {
      error = path + ":" + std::to_string(out.vehicle_line) + ": vehicle " + vehicle.string() + ": " + why;
      return false;
    }
    out.vehicle = v;
  }
  return true;
}

}  // namespace qrsim
