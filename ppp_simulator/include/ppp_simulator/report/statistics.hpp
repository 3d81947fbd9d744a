#pragma once

#include <string>
#include <vector>

#include "ppp_simulator/report/pass_rates.hpp"

namespace ppp {
namespace simulator {

/// Result of a two-sided Mann–Whitney U test of sample a against sample b.
struct MannWhitney {
  int n_a = 0;     ///< Size of sample a.
  int n_b = 0;     ///< Size of sample b.
  double u_a = 0;  ///< U of a: pairs (a_i, b_j) with a_i > b_j, ties counting one half; u_a + u_b = n_a n_b.
  double u_b = 0;  ///< U of b, likewise.
  double u = 0;    ///< min(u_a, u_b), the statistic printed in tables.
  double z = 0;    ///< (u_a − n_a n_b / 2) / σ: positive when a tends to be larger; 0 when σ = 0.
  double p = 1;    ///< Two-sided p-value of the normal approximation, erfc(|z| / √2); 1 when σ = 0.
};

/// Mann–Whitney U test: average ranks for ties, U_a = R_a − n_a(n_a + 1)/2, and the normal approximation with
/// the tie-corrected variance σ² = n_a n_b / 12 · ((N + 1) − Σ(t³ − t) / (N(N − 1))), N = n_a + n_b, t the size
/// of each group of tied values. No continuity correction is applied, so p is slightly smaller than with
/// one; the approximation is rough below about 8 values per sample. When every value is tied (σ = 0),
/// z = 0 and p = 1. Values must be finite.
/// @throws InvalidArgument naming "a" or "b" when that sample is empty or holds a NaN or infinite value.
MannWhitney mannWhitneyU(const std::vector<double>& a, const std::vector<double>& b);

/// One agent's per-PPP pass rates on two sets, compared.
struct AgentComparison {
  std::string agent;  ///< Agent configuration name.
  double mean_a = 0;  ///< Mean per-PPP pass rate on set a, in [0, 1] (the set's mean_rate).
  double mean_b = 0;  ///< Mean per-PPP pass rate on set b, in [0, 1].
  MannWhitney test;   ///< Mann–Whitney U test of the per-PPP pass rates of set a against those of set b.
};

/// For every agent of the table (in its order) with results on both sets, the Mann–Whitney U test of its
/// per-PPP pass rates on `set_a` against those on `set_b`; agents missing from either set are left out.
/// @throws InvalidArgument naming "set_a" or "set_b" (and the set) when the table has no such set.
std::vector<AgentComparison> compareSets(const PassRateTable& rates, const std::string& set_a,
                                         const std::string& set_b);

}  // namespace simulator
}  // namespace ppp
