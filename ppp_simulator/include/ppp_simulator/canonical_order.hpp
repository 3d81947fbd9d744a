#pragma once

#include <string>
#include <vector>

#include "ppp_core/stop.hpp"
#include "ppp_agents/episode_result.hpp"
#include "ppp_simulator/experiment_config.hpp"
#include "ppp_simulator/experiment_runner.hpp"

namespace ppp {
namespace simulator {

/// Puts `rows` in canonical order (set, PPP, agent, run as the config lists them; PPP ids in text order), so the
/// finished results.csv does not depend on threads, batches or interruptions; returns whether any row moved
/// (rows already in that order, as ppp experiment appends them, are left alone). `path` is named in errors.
/// @throws ParseError (a row of a set or agent not in the experiment), Interrupted.
bool putInCanonicalOrder(std::vector<agents::EpisodeResult>* rows, const ExperimentConfig& config,
                         const std::vector<agents::PreparedSet>& sets, const std::string& path, const StopCheck& stop = {});

}  // namespace simulator
}  // namespace ppp
