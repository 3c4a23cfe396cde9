#include <sim/wiring.hpp>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace sim {
namespace {

bool read_ints(const std::string& text, size_t count, std::vector<int>& out, std::string& error) {
  std::istringstream in(text);
  std::string word;
  out.clear();
  while (in >> word) {
    char* end = nullptr;
    const long v = std::strtol(word.c_str(), &end, 10);
    if (end != word.c_str() + word.size() || v < -1000 || v > 1000) {
      error = "`" + word + "` is not a whole number";
      return false;
    }
    out.push_back(static_cast<int>(v));
  }
  if (out.size() != count) {
    error = "needs " + std::to_string(count) + (count == 1 ? " number" : " numbers") + ", not " +
            std::to_string(out.size());
    return false;
  }
  return true;
}

bool all_in(const std::vector<int>& v, std::initializer_list<int> allowed) {
  return std::all_of(v.begin(), v.end(),
                     [&](int x) { return std::find(allowed.begin(), allowed.end(), x) != allowed.end(); });
}

template <size_t N>
std::string joined(const std::array<int, N>& v) {
  std::string s;
  for (size_t i = 0; i < N; ++i) s += (i ? " " : "") + std::to_string(v[i]);
  return s;
}

// The mounting: the board turned by yaw about body z, then over about its own x.
Vec3 mounted(const Wiring& w, const Vec3& b) {
  Vec3 s = b;
  switch (w.imu_yaw_deg) {
    case 90: s = {b.y, -b.x, b.z}; break;
    case 180: s = {-b.x, -b.y, b.z}; break;
    case 270: s = {-b.y, b.x, b.z}; break;
    default: break;
  }
  if (w.imu_upside_down != 0) s = {s.x, -s.y, -s.z};
  return s;
}

Vec3 signed_axes(const std::array<int, 3>& signs, const Vec3& v) {
  return {signs[0] * v.x, signs[1] * v.y, signs[2] * v.z};
}

}  // namespace

bool is_wiring_name(const std::string& name) {
  for (const char* n :
       {"motor_outputs", "motor_reversed", "imu_mount_yaw_deg", "imu_upside_down", "gyro_signs", "accel_signs"}) {
    if (name == n) return true;
  }
  return false;
}

bool parse_wiring_row(const std::string& name, const std::string& values, Wiring& w, std::string& error) {
  std::vector<int> v;
  const auto fail = [&](const std::string& why) {
    error = name + ": " + why;
    return false;
  };
  if (name == "motor_outputs") {
    if (!read_ints(values, 4, v, error)) return fail(error);
    std::vector<int> sorted = v;
    std::sort(sorted.begin(), sorted.end());
    if (sorted != std::vector<int>{0, 1, 2, 3}) return fail("the rotors 0..3, each once (" + values + ")");
    std::copy(v.begin(), v.end(), w.rotor_of_output.begin());
  } else if (name == "motor_reversed") {
    if (!read_ints(values, 4, v, error)) return fail(error);
    if (!all_in(v, {0, 1})) return fail("0 or 1 per rotor");
    std::copy(v.begin(), v.end(), w.reversed.begin());
  } else if (name == "imu_mount_yaw_deg") {
    if (!read_ints(values, 1, v, error)) return fail(error);
    if (!all_in(v, {0, 90, 180, 270})) return fail("0, 90, 180 or 270");
    w.imu_yaw_deg = v[0];
  } else if (name == "imu_upside_down") {
    if (!read_ints(values, 1, v, error)) return fail(error);
    if (!all_in(v, {0, 1})) return fail("0 or 1");
    w.imu_upside_down = v[0];
  } else if (name == "gyro_signs" || name == "accel_signs") {
    if (!read_ints(values, 3, v, error)) return fail(error);
    if (!all_in(v, {1, -1})) return fail("1 or -1 per axis");
    std::copy(v.begin(), v.end(), (name == "gyro_signs" ? w.gyro_signs : w.accel_signs).begin());
  } else {
    return fail("not a wiring row");
  }
  return true;
}

std::string wiring_text(const Wiring& w) {
  const Wiring right;
  std::ostringstream out;
  if (w.rotor_of_output != right.rotor_of_output) out << "motor_outputs = " << joined(w.rotor_of_output) << "\n";
  if (w.reversed != right.reversed) out << "motor_reversed = " << joined(w.reversed) << "\n";
  if (w.imu_yaw_deg != 0) out << "imu_mount_yaw_deg = " << w.imu_yaw_deg << "\n";
  if (w.imu_upside_down != 0) out << "imu_upside_down = 1\n";
  if (w.gyro_signs != right.gyro_signs) out << "gyro_signs = " << joined(w.gyro_signs) << "\n";
  if (w.accel_signs != right.accel_signs) out << "accel_signs = " << joined(w.accel_signs) << "\n";
  return out.str();
}

Vec3 imu_gyro_axes(const Wiring& w, const Vec3& body) { return signed_axes(w.gyro_signs, mounted(w, body)); }
Vec3 imu_accel_axes(const Wiring& w, const Vec3& body) { return signed_axes(w.accel_signs, mounted(w, body)); }

}  // namespace sim
