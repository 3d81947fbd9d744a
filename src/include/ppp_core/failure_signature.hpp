#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "ppp_core/diagnosis.hpp"
#include "ppp_core/grid.hpp"

namespace ppp {

/// What a failure signature reads of one PPP, per cell: its fewest 4-connected moves from the start and to the goal
/// over the grid the robot moves on, and how many of its sides (and diagonal neighbours) obstacles and the map's
/// edge block. Built once per PPP; a signature then costs a pass over the run's cells.
class SignatureMap {
 public:
  /// An empty map (every signature reads as unreachable).
  SignatureMap() = default;
  /// `obstacles`: the PPP's grid (what sides are counted on); `motion`: the grid the robot moves on (its
  /// configuration space, or the PPP's grid for a point robot), of the same size.
  SignatureMap(const Grid& obstacles, const Grid& motion, Cell start, Cell goal);

  /// Fewest moves from the start to `c`, saturated at kFar; kUnreachable off the map or where it cannot be reached.
  int fromStart(Cell c) const { return read(from_start_, c); }
  /// Fewest moves from `c` to the goal, saturated at kFar; kUnreachable as fromStart().
  int toGoal(Cell c) const { return read(to_goal_, c); }
  /// The sides of `c` blocked by obstacles (0-4), by the map's edge (0-2), and its diagonal neighbours that are
  /// obstacles or off the map (0-4), packed as obstacle_sides | edge_sides << 3 | diagonals << 5.
  int shape(Cell c) const;
  /// The start cell.
  Cell start() const { return start_; }
  /// The goal cell.
  Cell goal() const { return goal_; }

  static constexpr int kFar = 254;          ///< Distances are saturated here: signatures tell no farther.
  static constexpr int kUnreachable = 255;  ///< A cell the robot cannot reach (or one off the map).

 private:
  int read(const std::vector<std::uint8_t>& field, Cell c) const;

  int width_ = 0;
  int height_ = 0;
  Cell start_;
  Cell goal_;
  std::vector<std::uint8_t> from_start_;
  std::vector<std::uint8_t> to_goal_;
  std::vector<std::uint8_t> shape_;
};

/// The failure signature of a failed or soft-failed run (docs/reference/signatures.md): how it failed and where,
/// "HOW/gG/sS/tT/wOeE", with "/GOeEdD" when the site is within 3 moves of the goal, e.g. "loop2/g4-7/s8-15/t2/w1e0"
/// or "missed_route/g2-3/s16-31/t1/w0e0/G1e0d2". HOW is the diagnosis (a loop with its period's class, a `reported`
/// ending as its reason); the site is where the run failed: the cell of a loop's, stuck or confined tail nearest
/// the goal, a wandering run's nearest approach, a detour's farthest excursion, else the cell it ended on; gG and sS
/// are the site's distance classes to the goal and from the start, tT the run's progress (cells entered before the
/// site against the fewest moves), wOeE the site's sides blocked by obstacles and by the edge, and the G part the
/// goal's own sides and blocked diagonals. Empty for a clean pass (an empty `d.kind`).
/// `cells[t]` is the robot's cell after t actions (or control periods; none: it stood on the start); `reason` is
/// the run's.
std::string failureSignature(const SignatureMap& map, const Diagnosis& d, const std::string& reason,
                             const std::vector<Cell>& cells);

/// The HOW part of a signature: the diagnosis' kind, "loop" with the class of its period (2, 3-4, 5-8, 9-16,
/// 17+), or for `reported` the run's reason.
std::string failureHow(const Diagnosis& d, const std::string& reason);

/// Whether `text` is a signature failureSignature() can write (or empty); `why` gets what is wrong when not.
bool isWellFormedSignature(std::string_view text, std::string* why = nullptr);

}  // namespace ppp
