#include <pc/platform/sim_process.hpp>

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>

extern char** environ;

namespace qrterm {
namespace {

constexpr const char* kSerialMarker = "serial on ";

uint64_t clock_ms() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<uint64_t>(ts.tv_sec) * 1000u + static_cast<uint64_t>(ts.tv_nsec) / 1000000u;
}

struct Pipe {
  int read = -1;
  int write = -1;
};

Pipe make_pipe() {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw SimError(std::string("cannot make a pipe: ") + std::strerror(errno));
  return {fds[0], fds[1]};
}

}  // namespace

std::string describe_wait_status(int status) {
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status))
    return "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  return "ended";
}

SimProcess::SimProcess(const std::string& program, const std::vector<std::string>& arguments, uint32_t timeout_ms) {
  if (::access(program.c_str(), F_OK) != 0) {
    throw SimError(
        "no simulator at " + program +
        " (build it: cmake --build --preset host; or name it with --sim PATH, or fly a QR with --port PATH)");
  }
  if (::access(program.c_str(), X_OK) != 0) throw SimError(program + " is not executable");
  spawn(program, arguments);
  wait_for_serial_line(program, timeout_ms);
}

void SimProcess::spawn(const std::string& program, const std::vector<std::string>& arguments) {
  const Pipe out = make_pipe();
  const Pipe err = make_pipe();
  // The truth channel: one end for us, the other the child's descriptor kTruthFd. Made after the
  // pipes, so neither end is descriptor 3 already (a dup2 onto itself would keep close-on-exec).
  int pair[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0)
    throw SimError(std::string("cannot make a socket pair: ") + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, out.write, 1);
  posix_spawn_file_actions_adddup2(&actions, err.write, 2);
  posix_spawn_file_actions_adddup2(&actions, pair[1], kTruthFd);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  // Its own process group: a ^C meant for the console must not kill the QR's world under it.
  // Default signal handling: the console ignores SIGPIPE, which a child would otherwise inherit.
  sigset_t defaults;
  sigemptyset(&defaults);
  for (int s : {SIGPIPE, SIGINT, SIGTERM, SIGHUP}) sigaddset(&defaults, s);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setpgroup(&attributes, 0);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);

  std::vector<std::string> words{program};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const int spawned = posix_spawn(&pid_, program.c_str(), &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(out.write);
  ::close(err.write);
  ::close(pair[1]);
  truth_ = LineReader(pair[0]);
  ::fcntl(pair[0], F_SETFL, O_NONBLOCK);
  out_ = LineReader(out.read);
  err_ = LineReader(err.read);
  ::fcntl(out.read, F_SETFL, O_NONBLOCK);
  ::fcntl(err.read, F_SETFL, O_NONBLOCK);
  if (spawned != 0) {
    pid_ = -1;
    close_channels();
    throw SimError("cannot start " + program + ": " + std::strerror(spawned));
  }
}

void SimProcess::wait_for_serial_line(const std::string& program, uint32_t timeout_ms) {
  const uint64_t deadline = clock_ms() + timeout_ms;
  bool out_open = true;
  bool err_open = true;
  while (serial_path_.empty()) {
    const uint64_t now = clock_ms();
    // Output closed: the child is ending (or has closed stdout, which is as bad); a moment lets
    // it be reaped so the message can say how it ended.
    if (!out_open) wait_ms(1000);
    std::optional<std::string> how = ended();
    if (how || now >= deadline || !out_open) {
      bool ignored = false;
      for (std::string& line : err_.read(ignored)) early_output_.push_back(std::move(line));
      const std::string seconds = std::to_string(timeout_ms / 1000) + "." + std::to_string(timeout_ms % 1000 / 100);
      std::string message = how        ? *how + " before naming its serial line"
                            : out_open ? program + " did not name its serial line within " + seconds + " s"
                                       : program + " closed its output without naming its serial line";
      for (const std::string& line : early_output_) message += "\n  " + line;
      if (!how) stop(0);
      close_channels();
      throw SimError(message);
    }
    pollfd fds[2] = {{out_.fd(), POLLIN, 0}, {err_.fd(), POLLIN, 0}};
    ::poll(fds, err_open ? 2 : 1, static_cast<int>(std::min<uint64_t>(deadline - now, 100)));
    for (std::string& line : out_.read(out_open)) {
      const size_t at = line.find(kSerialMarker);
      if (at != std::string::npos && serial_path_.empty()) {
        serial_path_ = line.substr(at + std::strlen(kSerialMarker));
        while (!serial_path_.empty() && (serial_path_.back() == ' ' || serial_path_.back() == '\r'))
          serial_path_.pop_back();
      } else {
        early_output_.push_back(std::move(line));
      }
    }
    if (err_open) {
      for (std::string& line : err_.read(err_open)) early_output_.push_back(std::move(line));
    }
  }
}

// A start that failed: the destructor will not run, so the pipes and the socket close here.
void SimProcess::close_channels() {
  ::close(out_.fd());
  ::close(err_.fd());
  ::close(truth_.fd());
}

SimProcess::~SimProcess() {
  stop(0);
  if (out_.fd() >= 0) ::close(out_.fd());
  if (err_.fd() >= 0) ::close(err_.fd());
  if (truth_.fd() >= 0) ::close(truth_.fd());
}

void SimProcess::send_truth_command(const std::string& line) {
  if (truth_.fd() < 0) return;
  // Short lines on a fresh socket: they fit; one that does not is dropped, never waited for.
  const ssize_t n = ::send(truth_.fd(), line.data(), line.size(), MSG_DONTWAIT | MSG_NOSIGNAL);
  (void)n;
}

std::optional<std::string> SimProcess::ended() {
  if (pid_ < 0) return std::nullopt;
  if (!reaped_) {
    int status = 0;
    const pid_t done = ::waitpid(pid_, &status, WNOHANG);
    if (done != pid_) return std::nullopt;
    reaped_ = true;
    status_text_ = "simulator " + describe_wait_status(status);
  }
  return status_text_;
}

bool SimProcess::wait_ms(uint32_t ms) {
  const uint64_t deadline = clock_ms() + ms;
  while (!ended()) {
    if (clock_ms() >= deadline) return false;
    ::usleep(10000);
  }
  return true;
}

void SimProcess::stop(uint32_t grace_ms) {
  if (pid_ < 0 || ended()) return;
  if (wait_ms(grace_ms)) return;
  ::kill(pid_, SIGTERM);
  if (wait_ms(1000)) return;
  ::kill(pid_, SIGKILL);
  wait_ms(1000);
}

}  // namespace qrterm
