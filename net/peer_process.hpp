#pragma once
// A co-simulation peer: a program covsim starts and talks to in frames (net/ns3_wire.hpp's
// {u32 type, u32 length, payload}) over a socket that is the program's standard input and
// output; its standard error is covsim's. Every failure is a PeerError naming the program:
// one that cannot start, exits or dies (with its status or signal), answers with an error
// frame (its text), sends a malformed or oversized frame, or does not answer within the
// time allowed. SIGINT and SIGTERM interrupt a wait (Interrupted). Destroying the process
// closes the socket, and a peer that has not exited a second later is killed.
#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "net/ns3_wire.hpp"

namespace covsim {

class PeerError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class PeerProcess {
 public:
  // `answer_timeout`: the longest wait for one answer, in seconds.
  PeerProcess(const std::filesystem::path& program, std::vector<std::string> args,
              double answer_timeout);
  PeerProcess(const PeerProcess&) = delete;
  PeerProcess& operator=(const PeerProcess&) = delete;
  ~PeerProcess();

  void send(ns3wire::FrameType type, const std::string& payload);
  // The next frame; its type and payload.
  std::uint32_t receive(std::string& payload);
  const std::string& name() const { return name_; }

 private:
  [[noreturn]] void died(const std::string& what);
  void read_exactly(char* data, std::size_t size);

  std::string name_;
  int fd_ = -1;
  pid_t pid_ = -1;
  double timeout_;
};

}  // namespace covsim
