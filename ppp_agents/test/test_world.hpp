#pragma once

// Test helpers: maps drawn as ASCII, agent configurations by type and a tiny episode loop applying the move
// model (the real engine lives in ppp_simulator, which depends on this package).

#include <string>
#include <vector>

#include "ppp_agents/agent.hpp"
#include "ppp_agents/agent_config.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace agents {
namespace test {

/// A map drawn as rows of '.' (free), '#' (obstacle), 'S' (start) and 'G' (goal).
struct World {
  Grid grid;
  Cell start;
  Cell goal;
};

/// Builds a world from its drawing.
inline World world(const std::vector<std::string>& rows) {
  World w{Grid(static_cast<int>(rows[0].size()), static_cast<int>(rows.size())), Cell{}, Cell{}};
  for (int y = 0; y < static_cast<int>(rows.size()); ++y) {
    for (int x = 0; x < static_cast<int>(rows[y].size()); ++x) {
      const char c = rows[y][x];
      if (c == '#') w.grid.setObstacle(Cell{x, y}, true);
      if (c == 'S') w.start = Cell{x, y};
      if (c == 'G') w.goal = Cell{x, y};
    }
  }
  return w;
}

/// The configuration of agent `type`, named after it, with the given handicaps.
inline AgentConfig config(const std::string& type, int memory = 0, double noise = 0.0) {
  AgentConfig c;
  c.name = type;
  c.type = type;
  c.memory_window = memory;
  c.sensor_noise = noise;
  return c;
}

/// What one episode did.
struct Outcome {
  bool passed = false;     ///< Stood on the goal within the budget.
  int steps = 0;           ///< Actions taken.
  int moves = 0;           ///< Actions that changed the cell (the path length).
  int bumps = 0;           ///< Moves into an obstacle or off the map.
  std::vector<Cell> path;  ///< Cells visited, the start first.
};

/// Runs one episode with the default move model: each step a scan, an action; a blocked move leaves the agent
/// in place and the next scan says bumped; ends on the goal or after `budget` actions.
inline Outcome runEpisode(Agent& agent, const World& w, std::uint64_t seed, double noise = 0.0, int budget = 300,
                          bool prior_map = false, int range = 2) {
  const SensorModel sensor(SensorOptions{range, noise});
  EpisodeInfo info;
  info.width = w.grid.width();
  info.height = w.grid.height();
  info.start = w.start;
  info.goal = w.goal;
  info.seed = seed;
  info.prior_map = prior_map ? &w.grid : nullptr;
  agent.reset(info);
  Outcome out;
  Cell position = w.start;
  bool bumped = false;
  out.path.push_back(position);
  const std::uint64_t noise_seed = deriveSeed(seed, {1});
  while (position != w.goal && out.steps < budget) {
    const Scan scan(sensor, w.grid, position, w.goal, bumped, out.steps, noise_seed);
    const Action action = agent.act(scan);
    ++out.steps;
    const Cell next = target(position, action);
    bumped = false;
    if (action == Action::Stay) continue;
    if (w.grid.isFree(next)) {
      position = next;
      ++out.moves;
      out.path.push_back(position);
    } else {
      bumped = true;
      ++out.bumps;
    }
  }
  out.passed = position == w.goal;
  return out;
}

}  // namespace test
}  // namespace agents
}  // namespace ppp
