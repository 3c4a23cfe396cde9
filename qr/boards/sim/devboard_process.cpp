#include <qr/boards/sim/devboard_process.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace qrsim {
namespace {

int listen_at(const std::string& path) {
  const int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  if (path.size() >= sizeof address.sun_path) {
    close(fd);
    return -1;
  }
  std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
  if (bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0 || listen(fd, 1) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

// Accepts one connection, waiting at most `timeout_ms` and giving up early if QEMU has exited.
int accept_from(int listener, pid_t qemu, int timeout_ms) {
  for (int waited = 0; waited < timeout_ms; waited += 50) {
    pollfd p{listener, POLLIN, 0};
    if (poll(&p, 1, 50) > 0) return accept4(listener, nullptr, nullptr, SOCK_CLOEXEC);
    int status = 0;
    if (waitpid(qemu, &status, WNOHANG) == qemu) return -1;
  }
  return -1;
}

}  // namespace

bool DevboardProcess::start(const std::string& elf, uint32_t core_mhz, std::string& error) {
  if (access(elf.c_str(), R_OK) != 0) {
    error = "no devboard firmware at " + elf + " (build it: cmake --preset rv32 && cmake --build --preset rv32)";
    return false;
  }
  char dir[] = "/tmp/qrsim-devboard-XXXXXX";
  if (mkdtemp(dir) == nullptr) {
    error = std::string("cannot make a directory for the devboard's sockets: ") + std::strerror(errno);
    return false;
  }
  dir_ = dir;
  const std::string ground_path = dir_ + "/ground", link_path = dir_ + "/link";
  const int ground_listener = listen_at(ground_path), link_listener = listen_at(link_path);
  if (ground_listener < 0 || link_listener < 0) {
    error = "cannot listen on the devboard's sockets in " + dir_;
    if (ground_listener >= 0) close(ground_listener);
    if (link_listener >= 0) close(link_listener);
    return false;
  }

  std::vector<std::string> args = {
      "qemu-system-riscv32", "-M", "virt", "-bios", "none", "-nographic", "-monitor", "none",
      // Instructions counted exactly; no virtual clock to keep: the simulator stamps the time.
      "-icount", "shift=0,sleep=off",
      // The modern virtio-mmio interface (version 2), the one the board's driver speaks.
      "-global", "virtio-mmio.force-legacy=false", "-chardev", "socket,id=ground,path=" + ground_path, "-serial",
      "chardev:ground", "-chardev", "socket,id=link,path=" + link_path, "-device", "virtio-serial-device", "-device",
      "virtconsole,chardev=link", "-kernel", elf};
  if (core_mhz > 0) {
    // The core-speed word (qr/boards/rv32virt/virt_map.hpp): "CORE", then the MHz, little-endian.
    char data[32];
    std::snprintf(data, sizeof data, "0x%08X45524F43", static_cast<unsigned>(core_mhz));
    args.insert(args.end() - 2, {"-device", std::string("loader,addr=0x87FFFFF8,data-len=8,data=") + data});
  }
  const std::string log_path = dir_ + "/qemu.log";
  pid_ = fork();
  if (pid_ == 0) {
    // QEMU goes when we go, however we go: an orphaned board would spin on its link for ever.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    const int null = open("/dev/null", O_RDONLY);
    const int log = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (null >= 0) dup2(null, 0);
    if (log >= 0) {
      dup2(log, 1);
      dup2(log, 2);
    }
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    std::fprintf(stderr, "cannot run qemu-system-riscv32: %s (scripts/bootstrap installs it)\n", std::strerror(errno));
    _exit(127);
  }
  if (pid_ < 0) {
    error = std::string("cannot start QEMU: ") + std::strerror(errno);
    close(ground_listener);
    close(link_listener);
    return false;
  }
  // QEMU connects its chardevs in the order given.
  ground_fd_ = accept_from(ground_listener, pid_, 10000);
  link_fd_ = ground_fd_ < 0 ? -1 : accept_from(link_listener, pid_, 10000);
  close(ground_listener);
  close(link_listener);
  if (ground_fd_ < 0 || link_fd_ < 0) {
    error = "QEMU did not connect the devboard's streams: " + log();
    return false;
  }
  return true;
}

std::string DevboardProcess::log() const {
  std::ifstream in(dir_ + "/qemu.log");
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s.empty() ? "(QEMU said nothing)" : s;
}

void DevboardProcess::stop() {
  if (ground_fd_ >= 0) close(ground_fd_);
  if (link_fd_ >= 0) close(link_fd_);
  ground_fd_ = link_fd_ = -1;
  if (pid_ > 0) {
    kill(pid_, SIGKILL);
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
  }
  if (!dir_.empty()) {
    for (const char* name : {"/ground", "/link", "/qemu.log"}) unlink((dir_ + name).c_str());
    rmdir(dir_.c_str());
    dir_.clear();
  }
}

DevboardProcess::~DevboardProcess() { stop(); }

bool write_all(int fd, const uint8_t* bytes, size_t size) {
  while (size > 0) {
    const ssize_t n = send(fd, bytes, size, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

long read_some(int fd, uint8_t* bytes, size_t capacity, int timeout_ms) {
  for (;;) {
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, timeout_ms);
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) return 0;
    const ssize_t n = read(fd, bytes, capacity);
    if (n < 0 && errno == EINTR) continue;
    return n <= 0 ? -1 : static_cast<long>(n);
  }
}

}  // namespace qrsim
