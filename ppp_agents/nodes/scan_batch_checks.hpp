#pragma once

#include <memory>
#include <string>

#include "ppp_agents/agent.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_msgs/EpisodeStart.h"
#include "ppp_msgs/ScanBatch.h"

namespace ppp {
namespace agents {

/// Checks that a batch's per-scan arrays agree in length, its range is a sensor range and, for an agent that
/// reads windows, that it holds one window per scan. Returns the field at fault ("batch", "range", "cells")
/// and sets `what`, or returns "" when the batch is well formed.
std::string checkBatchShape(const ppp_msgs::ScanBatch& batch, bool reads_window, std::string* what);

/// An episode start as ppp types: the episode's info and, when sent, the true map.
struct ParsedStart {
  EpisodeInfo info;              ///< Size, start, goal and seed (prior_map left null).
  std::unique_ptr<Grid> prior;   ///< The true map, or null when none was sent.
};

/// Parses and checks an EpisodeStart. @throws InvalidArgument naming the field ("size", "start", "goal",
/// "prior_map").
ParsedStart parseEpisodeStart(const ppp_msgs::EpisodeStart& start);

/// Throws InvalidArgument naming `field` unless `cell` lies on a width x height grid.
void requireOnGrid(Cell cell, int width, int height, const char* field);

/// A message cell as a grid cell.
inline Cell toCell(const ppp_msgs::GridCell& cell) { return Cell{static_cast<int>(cell.x), static_cast<int>(cell.y)}; }

}  // namespace agents
}  // namespace ppp
