#pragma once

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>

#include <utility>

#include "grid_map.hpp"

namespace ppp {
namespace planners {

/// The map-frame point of a state of a 2-D ompl::base::RealVectorStateSpace (metres).
MapPoint pointOf(const ompl::base::State* state);

/// OMPL motion validation by the cells a straight motion walks through, exactly as the planner bridge expands
/// a path: a motion is valid when GridMap::segmentPassable accepts it (either way). States are map-frame points
/// of a 2-D ompl::base::RealVectorStateSpace. The map must outlive the validator.
class GridMotionValidator : public ompl::base::MotionValidator {
 public:
  /// Validates motions of `si`'s state space against `map`.
  GridMotionValidator(const ompl::base::SpaceInformationPtr& si, const GridMap& map)
      : ompl::base::MotionValidator(si), map_(map) {}

  /// True when every cell the motion walks through is passable.
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const override;

  /// As above; when invalid, also the last valid point of the motion (to within 1e-9 of its length), as a
  /// fraction in last_valid.second and, when last_valid.first is not null, as a state.
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                   std::pair<ompl::base::State*, double>& last_valid) const override;

 private:
  const GridMap& map_;
};

}  // namespace planners
}  // namespace ppp
