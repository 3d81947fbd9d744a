#pragma once

#include <cstddef>
#include <functional>

namespace ppp {

/// Calls `task(i)` once for every i in [0, count) on up to `threads` threads (0: one per core), each thread
/// taking the next index not yet taken, and returns when every call has returned. Tasks must not depend on one
/// another's order; results written by index come out the same for any `threads`.
/// @throws the exception of the lowest index whose task threw, after every task has ended.
void parallelFor(std::size_t count, int threads, const std::function<void(std::size_t)>& task);

}  // namespace ppp
