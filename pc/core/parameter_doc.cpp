#include <pc/core/parameter_doc.hpp>

#include <common/parameter_table.hpp>
#include <pc/core/param_file.hpp>

namespace qrterm {
namespace {

// The real value of a raw integer as the console writes it in parameter files.
std::string real(const wire::ParameterSpec& spec, int32_t raw) { return format_real(spec, raw); }

std::string q_format(const wire::ParameterSpec& spec) {
  return "Q" + std::to_string(spec.frac_bits) + " (" +
         (spec.frac_bits == 0 ? std::string("integer") : "1/" + std::to_string(int64_t{1} << spec.frac_bits)) + ")";
}

std::string line_of(const std::string& text, size_t number) {
  size_t start = 0;
  for (size_t n = 1; n < number && start != std::string::npos; ++n) {
    start = text.find('\n', start);
    if (start != std::string::npos) ++start;
  }
  if (start == std::string::npos || start >= text.size()) return "(end of file)";
  const size_t end = text.find('\n', start);
  return text.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

}  // namespace

std::string parameters_markdown() {
  std::string text =
      "# Parameters\n"
      "\n"
      "<!-- Generated from common/parameter_table.hpp by `qrparams --markdown`; do not edit by hand.\n"
      "     Regenerate: build/host/pc/qrparams --markdown > docs/parameters.md -->\n"
      "\n"
      "Every tunable of the QR, as the shared table `common/parameter_table.hpp` defines it: the QR\n"
      "range-checks every `param_set` against it (nack `bad_value` outside the range), and the console\n"
      "(`qrterm`), its parameter file and `qrsim --param` use the same names. The wire carries the raw\n"
      "integer (`param_set`, `param_report`, [protocol.md section 9](protocol.md)); the real value is\n"
      "raw / 2^frac in the unit named, and the parameter file and `qrsim --param` take real values.\n"
      "A name ends in its unit where it has one (`_ms`, `_hz`, `_mv`, `_mrad`, `_rad_s`).\n"
      "\n"
      "| id | name | unit | Q format | range, raw | range, real | default, raw | default, real | meaning |\n"
      "| ---: | --- | --- | --- | --- | --- | ---: | ---: | --- |\n";
  for (const wire::ParameterSpec& spec : wire::kParameterTable) {
    text += "| " + std::to_string(static_cast<unsigned>(spec.id)) + " | `" + spec.name + "` | " + spec.unit + " | " +
            q_format(spec) + " | " + std::to_string(spec.min) + " .. " + std::to_string(spec.max) + " | " +
            real(spec, spec.min) + " .. " + real(spec, spec.max) + " | " + std::to_string(spec.default_value) + " | " +
            real(spec, spec.default_value) + " | " + spec.meaning + " |\n";
  }
  text +=
      "\n"
      "Engine units are the 0..1000 engine scale. Thrust units are the per-engine thrust the\n"
      "controllers' moments are expressed in: 1000 = one engine at full speed, an engine at command ae\n"
      "gives ae²/1000 ([signal-chain.md](signal-chain.md), engine mapping). `attitude_c1` and\n"
      "`attitude_c2` are the divisors of the attitude estimator, a complementary filter (not a Kalman\n"
      "filter): the angle follows the accelerometer with a time constant of C1 samples, and the gyro\n"
      "bias loop is critically damped at C2 = 4 C1².\n"
      "\n"
      "Angles are in mrad (1000 mrad = 57.3 deg); the console's parameter screen shows each beside its value in\n"
      "degrees. Full roll or pitch stick in full control and height hold asks for `max_tilt_mrad` as the angle\n"
      "set-point, a stick half way for half of it: at most 698 mrad, 40 deg. `tilt_limit_mrad` is no stick's\n"
      "angle but the tilt beyond which the QR panics (785 mrad, 45 deg, by default).\n";
  return text;
}

std::string first_difference(const std::string& expected, const std::string& text) {
  if (expected == text) return "";
  size_t line = 1;
  size_t i = 0;
  while (i < expected.size() && i < text.size() && expected[i] == text[i]) {
    if (expected[i] == '\n') ++line;
    ++i;
  }
  return "line " + std::to_string(line) + ": expected \"" + line_of(expected, line) + "\", found \"" +
         line_of(text, line) + "\"";
}

}  // namespace qrterm
