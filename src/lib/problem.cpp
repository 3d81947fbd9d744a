#include "ppp_core/problem.hpp"

#include <algorithm>
#include <string>

#include "ppp_core/error.hpp"

namespace ppp {

namespace {

struct ShapeKeyword {
  Shape shape;
  const char* name;
};

constexpr ShapeKeyword kShapeKeywords[] = {
    {Shape::HorizontalBar, "hbar"}, {Shape::VerticalBar, "vbar"}, {Shape::DiagonalDown, "diag_down"},
    {Shape::DiagonalUp, "diag_up"}, {Shape::Block, "block"},
};

void validateCell(Cell c, int width, int height, const char* what) {
  if (c.x < 0 || c.y < 0 || c.x >= width || c.y >= height) {
    throw InvalidArgument(what, "cell " + cellText(c) + " is outside the " + std::to_string(width) + "x" +
                                    std::to_string(height) + " grid");
  }
}

}  // namespace

const char* shapeName(Shape shape) {
  for (const auto& k : kShapeKeywords) {
    if (k.shape == shape) return k.name;
  }
  return "unknown";
}

bool parseShape(const std::string& name, Shape* shape) {
  for (const auto& k : kShapeKeywords) {
    if (name == k.name) {
      *shape = k.shape;
      return true;
    }
  }
  return false;
}

Problem Problem::empty(int width, int height, int max_obstacles) {
  Problem p;
  p.width = width;
  p.height = height;
  p.start = Cell{0, 0};
  p.goal = Cell{width - 1, height - 1};
  p.max_obstacles = max_obstacles;
  return p;
}

bool operator==(const Problem& a, const Problem& b) {
  return a.width == b.width && a.height == b.height && a.start == b.start && a.goal == b.goal &&
         a.max_obstacles == b.max_obstacles && a.obstacles == b.obstacles && a.metadata == b.metadata;
}

std::vector<Cell> obstacleCells(const Obstacle& o, int width, int height) {
  std::vector<Cell> cells;
  auto add = [&](int x, int y) {
    if (x >= 0 && y >= 0 && x < width && y < height) cells.push_back(Cell{x, y});
  };
  switch (o.shape) {
    case Shape::HorizontalBar:
      for (int i = 0; i < o.length; ++i) add(o.x + i, o.y);
      break;
    case Shape::VerticalBar:
      for (int i = 0; i < o.length; ++i) add(o.x, o.y + i);
      break;
    case Shape::DiagonalDown:
      for (int i = 0; i < o.length; ++i) add(o.x + i, o.y + i);
      break;
    case Shape::DiagonalUp:
      for (int i = 0; i < o.length; ++i) add(o.x + i, o.y - i);
      break;
    case Shape::Block:
      for (int dy = 0; dy < o.height; ++dy) {
        for (int dx = 0; dx < o.length; ++dx) add(o.x + dx, o.y + dy);
      }
      break;
  }
  return cells;
}

void validateObstacle(const Obstacle& o, int width, int height, const std::string& what) {
  validateCell(Cell{o.x, o.y}, width, height, what.c_str());
  const int longest = std::max(width, height);
  if (o.shape == Shape::Block) {
    if (o.length < 1 || o.length > width) {
      throw InvalidArgument(what, "block width " + std::to_string(o.length) + " outside [1, " +
                                      std::to_string(width) + "]");
    }
    if (o.height < 1 || o.height > height) {
      throw InvalidArgument(what, "block height " + std::to_string(o.height) + " outside [1, " +
                                      std::to_string(height) + "]");
    }
  } else {
    if (o.length < 1 || o.length > longest) {
      throw InvalidArgument(what, std::string(shapeName(o.shape)) + " length " + std::to_string(o.length) +
                                      " outside [1, " + std::to_string(longest) + "]");
    }
    if (o.height != 1) throw InvalidArgument(what, "bars have height 1, got " + std::to_string(o.height));
  }
}

void validateProblem(const Problem& p) {
  validateGridSize(p.width, p.height);
  validateCell(p.start, p.width, p.height, "start");
  validateCell(p.goal, p.width, p.height, "goal");
  if (p.start == p.goal) throw InvalidArgument("goal", "must differ from start " + cellText(p.start));
  if (p.max_obstacles < 0 || p.max_obstacles > kMaxObstacleBudget) {
    throw InvalidArgument("max_obstacles", "expected an integer in [0, " + std::to_string(kMaxObstacleBudget) +
                                               "], got " + std::to_string(p.max_obstacles));
  }
  if (static_cast<int>(p.obstacles.size()) > p.max_obstacles) {
    throw InvalidArgument("obstacles", std::to_string(p.obstacles.size()) + " descriptors exceed max_obstacles " +
                                           std::to_string(p.max_obstacles));
  }
  for (std::size_t i = 0; i < p.obstacles.size(); ++i) {
    validateObstacle(p.obstacles[i], p.width, p.height, "obstacle " + std::to_string(i + 1));
  }
}

Grid decodeGrid(const Problem& p) {
  Grid grid(p.width, p.height);
  for (const Obstacle& o : p.obstacles) {
    for (Cell c : obstacleCells(o, p.width, p.height)) grid.setObstacle(c, true);
  }
  grid.setObstacle(p.start, false);
  grid.setObstacle(p.goal, false);
  return grid;
}

Problem problemFromGrid(const Grid& grid, Cell start, Cell goal) {
  Problem p = Problem::empty(grid.width(), grid.height(), 0);
  p.start = start;
  p.goal = goal;
  validateProblem(p);
  if (grid.isObstacle(start)) throw InvalidArgument("start", "cell " + cellText(start) + " is an obstacle");
  if (grid.isObstacle(goal)) throw InvalidArgument("goal", "cell " + cellText(goal) + " is an obstacle");
  for (int y = 0; y < grid.height(); ++y) {
    int x = 0;
    while (x < grid.width()) {
      if (!grid.isObstacle(Cell{x, y})) {
        ++x;
        continue;
      }
      const int begin = x;
      while (x < grid.width() && grid.isObstacle(Cell{x, y})) ++x;
      if (p.obstacles.size() >= static_cast<std::size_t>(kMaxObstacleBudget)) {
        throw InvalidArgument("obstacles", "more than " + std::to_string(kMaxObstacleBudget) +
                                               " horizontal obstacle runs; the map is too fragmented for an "
                                               "obstacle budget");
      }
      p.obstacles.push_back(Obstacle{Shape::HorizontalBar, begin, y, x - begin, 1});
    }
  }
  p.max_obstacles = static_cast<int>(p.obstacles.size());
  return p;
}

const std::string* findMetadata(const Metadata& metadata, const std::string& key) {
  for (const auto& entry : metadata) {
    if (entry.first == key) return &entry.second;
  }
  return nullptr;
}

void setMetadata(Metadata* metadata, const std::string& key, const std::string& value) {
  for (auto& entry : *metadata) {
    if (entry.first == key) {
      entry.second = value;
      return;
    }
  }
  metadata->emplace_back(key, value);
}

}  // namespace ppp
