#include "ppp_core/failure_signature.hpp"

#include <algorithm>
#include <cstring>

#include "ppp_core/reachability.hpp"

namespace ppp {

namespace {

/// The distances' classes: 0, 1, 2-3, 4-7, 8-15, 16-31, 32-63, 64+ (doubling), x for a cell the robot cannot reach.
const char* distanceClass(int moves) {
  if (moves >= SignatureMap::kUnreachable) return "x";
  if (moves >= 64) return "64+";
  if (moves >= 32) return "32-63";
  if (moves >= 16) return "16-31";
  static const char* const kClasses[] = {"0", "1", "2-3", "2-3", "4-7", "4-7", "4-7", "4-7",
                                         "8-15", "8-15", "8-15", "8-15", "8-15", "8-15", "8-15", "8-15"};
  return kClasses[moves];
}

/// A loop period's class: 2, 3-4, 5-8, 9-16, 17+.
std::string periodClass(int period) {
  if (period <= 2) return "2";
  if (period <= 4) return "3-4";
  if (period <= 8) return "5-8";
  if (period <= 16) return "9-16";
  return "17+";
}

std::vector<std::uint8_t> saturated(const std::vector<int>& distances) {
  std::vector<std::uint8_t> field(distances.size());
  for (std::size_t i = 0; i < distances.size(); ++i) {
    const int d = distances[i];
    field[i] = static_cast<std::uint8_t>(d < 0 ? SignatureMap::kUnreachable : std::min(d, SignatureMap::kFar));
  }
  return field;
}

/// What the site's and the goal's shapes say: "w<obstacle sides>e<edge sides>", and "d<diagonals>" when asked.
std::string shapeText(int shape, bool diagonals) {
  std::string text = "w" + std::to_string(shape & 7) + "e" + std::to_string((shape >> 3) & 3);
  if (diagonals) text += "d" + std::to_string(shape >> 5);
  return text;
}

}  // namespace

std::string failureHow(const Diagnosis& d, const std::string& reason) {
  const std::string kind = d.kind;
  if (kind == diagnosis::kLoop) return "loop" + periodClass(d.period);
  if (kind == diagnosis::kReported) return reason;
  return kind;
}

namespace {

/// The step of `cells` where the run failed (see failureSignature()).
std::size_t siteStep(const SignatureMap& map, const Diagnosis& d, const std::vector<Cell>& cells) {
  const std::string kind = d.kind;
  const bool tail = kind == diagnosis::kLoop || kind == diagnosis::kStuck || kind == diagnosis::kConfined;
  if (kind == diagnosis::kDetour) {
    std::size_t best = 0;
    int farthest = -1;
    for (std::size_t t = 0; t < cells.size(); ++t) {
      const int excess = map.fromStart(cells[t]) + map.toGoal(cells[t]);
      if (excess > farthest) farthest = excess, best = t;
    }
    return best;
  }
  if (!tail && kind != diagnosis::kWandering) return cells.size() - 1;
  const std::size_t first = tail && d.step >= 0 ? std::min<std::size_t>(static_cast<std::size_t>(d.step), cells.size() - 1) : 0;
  std::size_t best = first;
  for (std::size_t t = first; t < cells.size(); ++t) {
    if (map.toGoal(cells[t]) < map.toGoal(cells[best])) best = t;
  }
  return best;
}

/// The class of the cells a run entered before its site against the fewest moves from start to goal: 0 below
/// half of them, 1 up to as many, 2 up to twice, 3 up to four times, 4 beyond.
char progressClass(const std::vector<Cell>& cells, std::size_t site, int fewest) {
  long entered = 0;
  for (std::size_t t = 1; t <= site && t < cells.size(); ++t) entered += cells[t] != cells[t - 1] ? 1 : 0;
  const double ratio = static_cast<double>(entered) / std::max(1, fewest);
  return ratio < 0.5 ? '0' : ratio <= 1 ? '1' : ratio <= 2 ? '2' : ratio <= 4 ? '3' : '4';
}

constexpr int kNearGoal = 3;  // a site this near the goal (in moves) adds the goal's shape

}  // namespace

SignatureMap::SignatureMap(const Grid& obstacles, const Grid& motion, Cell start, Cell goal)
    : width_(obstacles.width()), height_(obstacles.height()), start_(start), goal_(goal),
      from_start_(saturated(stepDistances(motion, start))), to_goal_(saturated(stepDistances(motion, goal))),
      shape_(static_cast<std::size_t>(obstacles.size())) {
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      int sides = 0, edges = 0, diagonals = 0;
      for (const Cell s : {Cell{1, 0}, Cell{0, 1}, Cell{-1, 0}, Cell{0, -1}}) {
        const Cell n{x + s.x, y + s.y};
        if (!obstacles.contains(n)) {
          ++edges;
        } else if (obstacles.isObstacle(n)) {
          ++sides;
        }
      }
      for (const Cell s : {Cell{1, 1}, Cell{-1, 1}, Cell{-1, -1}, Cell{1, -1}}) {
        const Cell n{x + s.x, y + s.y};
        if (!obstacles.contains(n) || obstacles.isObstacle(n)) ++diagonals;
      }
      shape_[static_cast<std::size_t>(y * width_ + x)] = static_cast<std::uint8_t>(sides | edges << 3 | diagonals << 5);
    }
  }
}

int SignatureMap::read(const std::vector<std::uint8_t>& field, Cell c) const {
  if (c.x < 0 || c.y < 0 || c.x >= width_ || c.y >= height_ || field.empty()) return kUnreachable;
  return field[static_cast<std::size_t>(c.y * width_ + c.x)];
}

int SignatureMap::shape(Cell c) const {
  if (c.x < 0 || c.y < 0 || c.x >= width_ || c.y >= height_ || shape_.empty()) return 0;
  return shape_[static_cast<std::size_t>(c.y * width_ + c.x)];
}

std::string failureSignature(const SignatureMap& map, const Diagnosis& d, const std::string& reason,
                             const std::vector<Cell>& cells) {
  if (d.kind[0] == '\0') return "";
  const std::size_t step = cells.empty() ? 0 : siteStep(map, d, cells);
  const Cell site = cells.empty() ? map.start() : cells[step];
  const int to_goal = map.toGoal(site);
  std::string text = failureHow(d, reason);
  text += "/g";
  text += distanceClass(to_goal);
  text += "/s";
  text += distanceClass(map.fromStart(site));
  text += "/t";
  text += progressClass(cells, step, map.fromStart(map.goal()));
  text += '/';
  text += shapeText(map.shape(site), false);
  if (to_goal <= kNearGoal) text += "/G" + shapeText(map.shape(map.goal()), true).substr(1);
  return text;
}

bool isWellFormedSignature(std::string_view text, std::string* why) {
  const auto fail = [why](const std::string& what) {
    if (why != nullptr) *why = what;
    return false;
  };
  if (text.empty()) return true;
  std::vector<std::string_view> parts;
  for (std::size_t pos = 0;;) {
    const std::size_t slash = text.find('/', pos);
    parts.push_back(text.substr(pos, slash == std::string_view::npos ? std::string_view::npos : slash - pos));
    if (slash == std::string_view::npos) break;
    pos = slash + 1;
  }
  if (parts.size() != 5 && parts.size() != 6) return fail("expected HOW/gG/sS/tT/wOeE[/GOeEdD], got '" + std::string(text) + "'");
  if (parts[0].empty() || parts[0].find_first_of(" ,\"") != std::string_view::npos) return fail("an empty or spaced HOW");
  const auto is_class = [](std::string_view c) {
    for (const char* k : {"0", "1", "2-3", "4-7", "8-15", "16-31", "32-63", "64+", "x"}) {
      if (c == k) return true;
    }
    return false;
  };
  if (parts[1].size() < 2 || parts[1][0] != 'g' || !is_class(parts[1].substr(1))) return fail("a bad goal distance '" + std::string(parts[1]) + "'");
  if (parts[2].size() < 2 || parts[2][0] != 's' || !is_class(parts[2].substr(1))) return fail("a bad start distance '" + std::string(parts[2]) + "'");
  const auto is_shape = [](std::string_view s, char lead, bool diagonals) {
    const std::size_t size = diagonals ? 6 : 4;
    return s.size() == size && s[0] == lead && s[1] >= '0' && s[1] <= '4' && s[2] == 'e' && s[3] >= '0' && s[3] <= '2' &&
           s[1] - '0' + s[3] - '0' <= 4 && (!diagonals || (s[4] == 'd' && s[5] >= '0' && s[5] <= '4'));
  };
  if (parts[3].size() != 2 || parts[3][0] != 't' || parts[3][1] < '0' || parts[3][1] > '4') {
    return fail("a bad progress '" + std::string(parts[3]) + "'");
  }
  if (!is_shape(parts[4], 'w', false)) return fail("a bad site shape '" + std::string(parts[4]) + "'");
  const bool near = parts[1] == "g0" || parts[1] == "g1" || parts[1] == "g2-3";
  if (near != (parts.size() == 6)) return fail("the goal's shape is given exactly when the site is within 3 moves of it");
  if (parts.size() == 6 && !is_shape(parts[5], 'G', true)) return fail("a bad goal shape '" + std::string(parts[5]) + "'");
  return true;
}

}  // namespace ppp
