#include "grid_motion_validator.hpp"

#include <ompl/base/spaces/RealVectorStateSpace.h>

namespace ppp {
namespace planners {

namespace {

MapPoint between(MapPoint a, MapPoint b, double t) { return MapPoint{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}; }

}  // namespace

MapPoint pointOf(const ompl::base::State* state) {
  const double* values = state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
  return MapPoint{values[0], values[1]};
}

bool GridMotionValidator::checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const {
  const bool valid = map_.segmentPassable(pointOf(s1), pointOf(s2));
  ++(valid ? valid_ : invalid_);
  return valid;
}

bool GridMotionValidator::checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                                      std::pair<ompl::base::State*, double>& last_valid) const {
  if (checkMotion(s1, s2)) return true;
  // Bisection on the fraction t: the motion from s1 to the point at `valid` stays passable, to `invalid` not.
  const MapPoint from = pointOf(s1);
  const MapPoint to = pointOf(s2);
  double valid = 0.0;
  double invalid = 1.0;
  while (invalid - valid > 1e-9) {
    const double t = 0.5 * (valid + invalid);
    (map_.segmentPassable(from, between(from, to, t)) ? valid : invalid) = t;
  }
  last_valid.second = valid;
  if (last_valid.first != nullptr) si_->getStateSpace()->interpolate(s1, s2, valid, last_valid.first);
  return false;
}

}  // namespace planners
}  // namespace ppp
