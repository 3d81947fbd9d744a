#include "ppp_agents/bumper_agent.hpp"

namespace ppp {
namespace agents {

namespace {

int moveIndex(Action action) { return static_cast<int>(action) - 1; }

}  // namespace

BumperAgent::BumperAgent(bool decision, const AgentBehaviour& behaviour) : decision_(decision), behaviour_(behaviour) {}

void BumperAgent::reset(const EpisodeInfo& info) {
  width_ = info.width;
  memory_.reset(info.width, info.height, behaviour_.memory_window, behaviour_.memory_scans);
  navigator_.reset(info.width, info.height);
  rng_ = Rng(info.seed);
  goal_seen_ = false;
  direction_ = static_cast<int>(rng_.below(4));
  last_ = direction_;
  if (decision_) tried_.assign(static_cast<std::size_t>(info.width) * static_cast<std::size_t>(info.height), 0);
}

int BumperAgent::turn(Cell position, int bumped) {
  // Quarter turns: left or right of the bumped direction, never straight back.
  const unsigned turns = behaviour_.quarter_turns ? (1u << ((bumped + 1) % 4)) | (1u << ((bumped + 3) % 4)) : 0xFu;
  const auto anyTurn = [&] {
    if (behaviour_.quarter_turns) return (bumped + (rng_.below(2) != 0 ? 1 : 3)) % 4;
    return (bumped + 1 + static_cast<int>(rng_.below(3))) % 4;
  };
  if (decision_) {
    std::uint8_t& tried = tried_[static_cast<std::size_t>(position.y) * width_ + position.x];
    tried = static_cast<std::uint8_t>(tried | (1u << bumped));
    const unsigned untried = ~static_cast<unsigned>(tried) & turns;
    int chosen;
    if (untried != 0) {
      const int count = __builtin_popcount(untried);
      int k = count == 1 ? 0 : static_cast<int>(rng_.below(static_cast<std::uint64_t>(count)));
      chosen = 0;
      for (unsigned bits = untried;; bits &= bits - 1) {
        if (k-- == 0) {
          chosen = __builtin_ctz(bits);
          break;
        }
      }
    } else {
      chosen = anyTurn();
    }
    tried = static_cast<std::uint8_t>(tried | (1u << chosen));
    return chosen;
  }
  return anyTurn();
}

Action BumperAgent::act(const Scan& scan) {
  const Cell position = scan.position();
  if (behaviour_.seek_goal && (goal_seen_ || goalNearby(scan, behaviour_.goal_range))) {
    memory_.update(scan);
    Action action;
    if (navigator_.towardsSeenGoal(scan, memory_, behaviour_.goal_range, &goal_seen_, &action)) {
      last_ = moveIndex(action);
      return action;
    }
  }
  if (scan.bumped() && last_ >= 0) direction_ = turn(position, last_);
  last_ = direction_;
  return kMoves[direction_];
}

}  // namespace agents
}  // namespace ppp
