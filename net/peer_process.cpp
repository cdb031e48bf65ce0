#include "net/peer_process.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

#include "io/interrupt.hpp"
#include "net/ns3_wire.hpp"

extern char** environ;

namespace covsim {

namespace {

std::string exit_text(int status) {
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status))
    return std::string("was killed by signal ") + std::to_string(WTERMSIG(status)) + " (" +
           strsignal(WTERMSIG(status)) + ")";
  return "stopped";
}

}  // namespace

PeerProcess::PeerProcess(const std::filesystem::path& program, std::vector<std::string> args,
                         double answer_timeout)
    : name_(program.string()), timeout_(answer_timeout) {
  int sv[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
    throw PeerError(name_ + ": cannot make a socket: " + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, sv[1], 0);
  posix_spawn_file_actions_adddup2(&actions, sv[1], 1);
  std::vector<char*> argv{const_cast<char*>(name_.c_str())};
  for (std::string& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  const int rc = ::posix_spawn(&pid_, name_.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(sv[1]);
  if (rc != 0) {
    ::close(sv[0]);
    throw PeerError(name_ + ": cannot start: " + std::strerror(rc));
  }
  fd_ = sv[0];
}

PeerProcess::~PeerProcess() {
  if (fd_ >= 0) ::close(fd_);
  if (pid_ <= 0) return;
  // The peer exits when its input ends; one that does not within a second is killed.
  for (int i = 0; i < 100; ++i) {
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) != 0) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ::kill(pid_, SIGKILL);
  int status = 0;
  ::waitpid(pid_, &status, 0);
}

void PeerProcess::died(const std::string& what) {
  // The peer's status, if it has ended (it usually has when its socket closes).
  int status = 0;
  for (int i = 0; i < 100 && pid_ > 0; ++i) {
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      throw PeerError(name_ + " " + exit_text(status) + " (" + what + ")");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  throw PeerError(name_ + ": " + what);
}

void PeerProcess::send(ns3wire::FrameType type, const std::string& payload) {
  const std::string bytes = ns3wire::frame(type, payload);  // header + payload
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    // MSG_NOSIGNAL: a peer that has died is an error here, not a SIGPIPE.
    const ssize_t n = ::send(fd_, p, left, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) died(std::string("cannot write to it: ") + std::strerror(errno));
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

void PeerProcess::read_exactly(char* data, std::size_t size) {
  using clock = std::chrono::steady_clock;
  // The time waited is summed over the polls, each counted for at most twice its length: a
  // process stopped and continued (Ctrl-Z, fg) has not waited for the peer all that time.
  constexpr int kPollMs = 100;
  double waited = 0.0;
  while (size > 0) {
    if (const int s = pending_interrupt()) throw Interrupted(s);
    pollfd pfd{fd_, POLLIN, 0};
    // Short polls, so that an interrupt is seen within a tenth of a second.
    const auto before = clock::now();
    const int ready = ::poll(&pfd, 1, kPollMs);
    if (ready < 0 && errno != EINTR)
      died(std::string("cannot wait for it: ") + std::strerror(errno));
    if (ready <= 0) {
      const double slice = std::chrono::duration<double>(clock::now() - before).count();
      waited += std::min(slice, 2e-3 * kPollMs);
      if (waited > timeout_)
        throw PeerError(fmt::format("{}: no answer within {:g} s", name_, timeout_));
      continue;
    }
    const ssize_t n = ::recv(fd_, data, size, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) died("its output ended");
    if (n < 0) died(std::string("cannot read from it: ") + std::strerror(errno));
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

std::uint32_t PeerProcess::receive(std::string& payload) {
  char bytes[8];
  read_exactly(bytes, sizeof bytes);
  const ns3wire::FrameHeader header = ns3wire::frame_header(bytes);
  if (header.length > ns3wire::kMaxPayload)
    throw PeerError(name_ + ": answered with a frame of " + std::to_string(header.length) +
                    " bytes, more than the protocol allows (not a covsim peer?)");
  payload.resize(header.length);
  read_exactly(payload.data(), payload.size());
  if (header.type == static_cast<std::uint32_t>(ns3wire::FrameType::error))
    died("it reported: " + payload);
  return header.type;
}

}  // namespace covsim
