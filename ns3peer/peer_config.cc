// SPDX-License-Identifier: GPL-2.0-or-later
#include "peer_config.h"

#include <sstream>
#include <stdexcept>

namespace covsim_peer {

PeerConfig parse_peer_config(const std::string& text) {
  PeerConfig c;
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    if (line.empty()) continue;
    std::istringstream in(line);
    std::string key;
    in >> key;
    const auto bad = [&]() {
      return std::invalid_argument("config line " + std::to_string(number) + ": '" + line + "'");
    };
    const auto number_of = [&](auto& v) {
      if (!(in >> v)) throw bad();
    };
    if (key == "robots") {
      number_of(c.robots);
      c.x.assign(c.robots, 0.0);
      c.y.assign(c.robots, 0.0);
    } else if (key == "run") {
      number_of(c.run);
    } else if (key == "standard") {
      number_of(c.standard);
    } else if (key == "rate") {
      number_of(c.rate);
    } else if (key == "tx_power_dbm") {
      number_of(c.tx_power_dbm);
    } else if (key == "propagation") {
      number_of(c.propagation);
    } else if (key == "exponent") {
      number_of(c.exponent);
    } else if (key == "reference_loss_db") {
      number_of(c.reference_loss_db);
    } else if (key == "reference_distance") {
      number_of(c.reference_distance);
    } else if (key == "max_range") {
      number_of(c.max_range);
    } else if (key == "nakagami_m") {
      number_of(c.nakagami_m);
    } else if (key == "wall_loss_db") {
      number_of(c.wall_loss_db);
    } else if (key == "wall") {
      Wall w{};
      if (!(in >> w.x1 >> w.y1 >> w.x2 >> w.y2)) throw bad();
      c.walls.push_back(w);
    } else if (key == "position") {
      std::uint32_t i = 0;
      double x = 0, y = 0;
      if (!(in >> i >> x >> y) || i >= c.robots) throw bad();
      c.x[i] = x;
      c.y[i] = y;
    } else {
      throw bad();
    }
    std::string extra;
    if (in >> extra) throw bad();
  }
  if (c.robots == 0) throw std::invalid_argument("config names no robots");
  return c;
}

}  // namespace covsim_peer
