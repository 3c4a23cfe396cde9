// Garbage that reaches the QR's receiver: how many frames random bytes make that it accepts, by
// type, against what the arithmetic expects (docs/protocol.md section 10). Commanding requests
// (mode changes, parameter sets, log start/stop, exit) must not come out of noise at any
// practical rate: they carry a 24-bit guard besides the 8-bit check.
//
// usage: wire-garbage-bench [--bytes N] [--seed S] [--require-no-guarded] [--check-doc FILE]
// Prints one JSON line: {"garbage_bytes": N, "accepted": {type: count, ...}, "accepted_guarded": G,
// "expected_per_1e12_bytes": {"unguarded_type": E, "guarded_total": G}, "seconds": T}.
// --require-no-guarded: exit 1 when any guarded frame was accepted.
// --check-doc FILE: exit 1 when the counts FILE quotes (docs/protocol.md section 10, "Measured by
// `wire-garbage-bench`": "NAME COUNT" for each unguarded type) are not this run's; the run must be
// the document's (10^9 bytes, seed 1), so a doc never quotes a figure the bench no longer measures.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include <common/frame_parser.hpp>

namespace {

// xorshift64*: fast, and the same bytes for the same seed everywhere.
struct Noise {
  uint64_t state;
  uint64_t next() {
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    return state * 0x2545F4914F6CDD1DULL;
  }
};

int usage(const char* why) {
  if (why != nullptr) std::fprintf(stderr, "wire-garbage-bench: %s\n", why);
  std::fprintf(why != nullptr ? stderr : stdout,
               "usage: wire-garbage-bench [--bytes N] [--seed S] [--require-no-guarded] [--check-doc FILE]\n"
               "  feeds N random bytes (default 1e8) to the QR's frame receiver and prints, as one JSON\n"
               "  line, the frames it accepted by type and the rates the arithmetic expects\n");
  return why != nullptr ? 2 : 0;
}

// The paragraph of `doc` that quotes this bench, from its name to the next blank line.
std::string quoting_paragraph(const std::string& doc) {
  const size_t at = doc.find("Measured by `wire-garbage-bench`");
  if (at == std::string::npos) return "";
  const size_t end = doc.find("\n\n", at);
  return doc.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

// Every unguarded PC -> QR type's count, as "name N" in the paragraph, is this run's.
bool doc_quotes(const std::string& path, const std::map<wire::MessageType, uint64_t>& accepted) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::string paragraph = quoting_paragraph(text.str());
  for (char& c : paragraph) c = c == '\n' ? ' ' : c;
  if (paragraph.empty()) {
    std::fprintf(stderr, "wire-garbage-bench: %s quotes no figure of this bench\n", path.c_str());
    return false;
  }
  bool ok = true;
  for (const wire::MessageSpec& spec : wire::kMessageTable) {
    if (spec.direction != wire::Direction::pc_to_qr || spec.guarded) continue;
    const auto found = accepted.find(spec.type);
    const uint64_t n = found == accepted.end() ? 0 : found->second;
    std::smatch m;
    if (!std::regex_search(paragraph, m, std::regex(std::string("\\b") + spec.name + " ([0-9]+)\\b")) ||
        std::stoull(m[1].str()) != n) {
      std::fprintf(stderr, "wire-garbage-bench: %s should say %s %llu\n", path.c_str(), spec.name,
                   static_cast<unsigned long long>(n));
      ok = false;
    }
  }
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  double bytes_wanted = 1e8;
  uint64_t seed = 1;
  bool require_no_guarded = false;
  std::string check_doc;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") return usage(nullptr);
    if (a == "--require-no-guarded") {
      require_no_guarded = true;
    } else if (a == "--check-doc" && i + 1 < argc) {
      check_doc = argv[++i];
    } else if ((a == "--bytes" || a == "--seed") && i + 1 < argc) {
      char* end = nullptr;
      const double v = std::strtod(argv[++i], &end);
      if (*end != '\0' || !(v >= 1) || v > 1e13) return usage(("bad number for " + a).c_str());
      if (a == "--bytes") bytes_wanted = v;
      else seed = static_cast<uint64_t>(v);
    } else {
      return usage(("unknown argument '" + a + "'").c_str());
    }
  }
  const uint64_t total = static_cast<uint64_t>(bytes_wanted);

  wire::FrameParser parser(wire::Listen::pc_to_qr);
  std::map<wire::MessageType, uint64_t> accepted;
  Noise noise{seed * 0x9E3779B97F4A7C15ULL + 1};
  const auto start = std::chrono::steady_clock::now();
  for (uint64_t done = 0; done < total;) {
    uint64_t word = noise.next();
    for (int k = 0; k < 8 && done < total; ++k, ++done, word >>= 8) {
      parser.push(static_cast<uint8_t>(word), [&](const wire::Frame& f) { ++accepted[f.type]; });
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // A random position starts an accepted frame of one given type when its byte is 'M', the next
  // is the type and the check matches: 2^-24 (a guarded type: 2^-48). Frames found by the re-scan
  // after a false start are positions too, so this holds per byte received.
  const double per_byte_unguarded = std::ldexp(1.0, -24);
  const double per_byte_guarded = std::ldexp(1.0, -48);
  uint64_t guarded_accepted = 0;
  size_t guarded_types = 0;
  std::printf("{\"garbage_bytes\": %llu, \"seed\": %llu, \"accepted\": {", static_cast<unsigned long long>(total),
              static_cast<unsigned long long>(seed));
  bool first = true;
  for (const wire::MessageSpec& spec : wire::kMessageTable) {
    if (spec.direction != wire::Direction::pc_to_qr) continue;
    const uint64_t n = accepted.count(spec.type) != 0 ? accepted[spec.type] : 0;
    if (spec.guarded) {
      guarded_accepted += n;
      ++guarded_types;
    }
    std::printf("%s\"%s\": %llu", first ? "" : ", ", spec.name, static_cast<unsigned long long>(n));
    first = false;
  }
  std::printf(
      "}, \"accepted_guarded\": %llu, \"expected_per_1e9_bytes\": {\"unguarded_type\": %.1f, "
      "\"guarded_total\": %.3g}, \"expected_per_1e12_bytes\": {\"guarded_total\": %.3g}, \"seconds\": %.1f}\n",
      static_cast<unsigned long long>(guarded_accepted), per_byte_unguarded * 1e9,
      per_byte_guarded * 1e9 * static_cast<double>(guarded_types),
      per_byte_guarded * 1e12 * static_cast<double>(guarded_types), seconds);
  if (require_no_guarded && guarded_accepted != 0) return 1;
  if (!check_doc.empty()) {
    if (total != 1000000000u || seed != 1) return usage("--check-doc: the document's run is --bytes 1e9 --seed 1");
    if (!doc_quotes(check_doc, accepted)) return 1;
  }
  return 0;
}
