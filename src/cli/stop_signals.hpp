#pragma once

#include "ppp_core/stop.hpp"

namespace ppp {
namespace cli {

/// Makes SIGINT and SIGTERM request a stop instead of killing the process, and returns the check long
/// computations ask (they then throw Interrupted, which runCommandLine reports with exit status 130).
StopCheck stopOnSignals();

}  // namespace cli
}  // namespace ppp
