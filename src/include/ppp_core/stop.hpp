#pragma once

#include <functional>

#include "ppp_core/error.hpp"

namespace ppp {

/// Asks whether a long computation should stop now (a signal arrived, the node is shutting down); an empty
/// check never stops.
using StopCheck = std::function<bool()>;

/// Thrown by a computation whose StopCheck said stop. What it had not finished it did not write, so a rerun
/// starts that part again and comes to the same result.
class Interrupted : public Error {
 public:
  Interrupted() : Error("interrupted") {}
};

/// @throws Interrupted when `stop` says stop.
inline void stopIfAsked(const StopCheck& stop) {
  if (stop && stop()) throw Interrupted();
}

}  // namespace ppp
