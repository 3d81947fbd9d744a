#include "ppp_generator/map_elites.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "ppp_core/barn_metrics.hpp"
#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_generator/initial_pool.hpp"
#include "ppp_generator/taxonomy.hpp"

namespace ppp {
namespace generator {

namespace {

constexpr int kCellPixels = 28;
constexpr int kMargin = 60;

double weightSum(const DifficultyWeights& w) {
  return std::abs(w.start) + std::abs(w.centre) + std::abs(w.top_right) + std::abs(w.bottom_left) +
         std::abs(w.goal) + std::abs(w.unused_obstacles) + std::abs(w.horizontal_openness) +
         std::abs(w.vertical_openness) + std::abs(w.one_turn_penalty);
}

std::size_t characterIndex(const std::string& name) {
  const auto& names = availableCharacterNames();
  const auto found = std::find(names.begin(), names.end(), name);
  if (found == names.end()) throw InvalidArgument("features", "unknown character '" + name + "'");
  return static_cast<std::size_t>(found - names.begin());
}

}  // namespace

FeatureRange featureRange(const std::string& name, const GeneratorOptions& o) {
  const double w = o.width;
  const double h = o.height;
  const int dx = std::abs(o.goalCell().x - o.startCell().x);
  const int dy = std::abs(o.goalCell().y - o.startCell().y);
  const double manhattan = dx + dy;
  const double most_advances = std::max(manhattan + 1.0, w * h / 2.0);
  characterIndex(name);
  if (name == "turns") return {0.0, w + h};
  if (name == "advances") return {manhattan, most_advances};
  if (name == "turns_plus_advances") return {manhattan, most_advances + w + h};
  if (name == "obstacles") return {0.0, static_cast<double>(std::max(1, o.max_obstacles))};
  if (name == "difficulty") return {0.0, std::max(1.0, weightSum(o.weights))};
  if (name == "barn_closest_obstacle") return {0.0, std::min(w, h) / 2};
  if (name == "barn_visibility") return {0.0, std::max(w, h) / 2};
  if (name == "barn_dispersion") return {0.0, BarnOptions{}.dispersion_rays / 2.0};
  if (name == "barn_characteristic_dimension") return {0.0, std::min(w, h)};
  if (name == "barn_tortuosity") return {manhattan / std::hypot(dx, dy), most_advances / std::hypot(dx, dy)};
  return {0.0, 1.0};
}

int binOf(double value, const FeatureRange& range, int bins) {
  const double share = (value - range.low) / (range.high - range.low);
  const int bin = static_cast<int>(std::floor(share * bins));
  return std::clamp(bin, 0, bins - 1);
}

Archive::Archive(std::vector<FeatureRange> ranges, int bins) : ranges_(std::move(ranges)), bins_(bins) {}

long Archive::cellOf(const std::vector<double>& features) const {
  long cell = 0;
  for (std::size_t f = 0; f < ranges_.size(); ++f) cell = cell * bins_ + binOf(features.at(f), ranges_[f], bins_);
  return cell;
}

bool Archive::offer(const Individual& individual, const std::vector<double>& features) {
  const long cell = cellOf(features);
  auto found = elites_.find(cell);
  if (found != elites_.end() && !(individual.score > found->second.individual.score)) return false;
  Elite elite;
  for (std::size_t f = 0; f < ranges_.size(); ++f) elite.bins.push_back(binOf(features[f], ranges_[f], bins_));
  elite.features = features;
  elite.individual = individual;
  elites_[cell] = std::move(elite);
  return true;
}

bool Archive::holds(const Individual& candidate) const {
  for (const auto& [cell, elite] : elites_) {
    if (elite.individual.grid_hash == candidate.grid_hash && elite.individual.grid == candidate.grid) return true;
  }
  return false;
}

namespace {

std::vector<FeatureRange> rangesOf(const GeneratorOptions& options) {
  options.validate();
  std::vector<FeatureRange> ranges;
  for (const std::string& name : options.features) ranges.push_back(featureRange(name, options));
  return ranges;
}

}  // namespace

MapElites::MapElites(const GeneratorOptions& options, Fitness fitness)
    : options_(options),
      fitness_(std::move(fitness)),
      rng_(options.seed),
      breeder_(options_, fitness_, &rng_),
      evaluator_(options.weights),
      archive_(rangesOf(options), options.bins),
      barn_features_(std::any_of(options.features.begin(), options.features.end(), [](const std::string& name) {
        const std::vector<std::string>& barn = barnCharacterNames();
        return std::find(barn.begin(), barn.end(), name) != barn.end();
      })) {}

std::vector<double> MapElites::featuresOf(const Individual& individual) {
  const Problem& problem = individual.problem;
  Grid space;  // the DPA in the robot's configuration space, one for both
  const DpaResult& dpa = dpa_.solve(motionGrid(individual.grid, options_.robot_radius, &space), problem.start, problem.goal);
  std::vector<double> all = characterVector(evaluator_.evaluate(problem, individual.grid, dpa));
  if (barn_features_) {
    const std::vector<double> metrics = barnCharacterVector(barnMetrics(individual.grid, dpa));
    all.insert(all.end(), metrics.begin(), metrics.end());
  }
  std::vector<double> features;
  for (const std::string& name : options_.features) features.push_back(all[characterIndex(name)]);
  return features;
}

std::vector<Individual> MapElites::run(const ProgressCallback& progress, long progress_interval,
                                       const StopCheck& stop) {
  stats_ = ArchiveStats{};
  archive_ = Archive(rangesOf(options_), options_.bins);
  auto offerAll = [&](std::vector<Individual>& children) {
    std::vector<Individual*> to_score;
    for (Individual& child : children) to_score.push_back(&child);
    breeder_.score(to_score);
    for (Individual& child : children) {
      if (archive_.holds(child)) {
        ++stats_.children_duplicate;
      } else if (archive_.offer(child, featuresOf(child))) {
        ++stats_.children_accepted;
      } else {
        ++stats_.children_rejected;
      }
    }
  };
  // Seed the archive with the initial pool's PPPs, then random valid ones.
  std::vector<Individual> batch = initialPoolIndividuals(options_, &breeder_);
  long redraws = 0;
  while (static_cast<int>(batch.size()) < options_.population) {
    stopIfAsked(stop);
    batch.push_back(breeder_.randomSolvable(&redraws));
  }
  offerAll(batch);
  auto best = [&]() {
    double value = 0, score = -1e300;
    for (const auto& [cell, elite] : archive_.elites()) {
      if (elite.individual.score > score) score = elite.individual.score, value = elite.individual.value;
    }
    return value;
  };
  const long round_size = breeder_.roundSize();
  for (long begin = 0; begin < options_.matings; begin += round_size) {
    stopIfAsked(stop);
    const long count = std::min(round_size, options_.matings - begin);
    std::vector<const Individual*> elites;
    for (const auto& [cell, elite] : archive_.elites()) elites.push_back(&elite.individual);
    batch.clear();
    for (long k = 0; k < count; ++k) {
      const Individual& a = *elites[rng_.below(elites.size())];
      const Individual& b = *elites[rng_.below(elites.size())];
      Individual children[2];
      breeder_.crossover(a.problem, b.problem, &children[0].problem, &children[1].problem);
      for (Individual& child : children) {
        breeder_.mutate(&child.problem);
        if (breeder_.decode(&child)) {
          batch.push_back(std::move(child));
        } else {
          ++stats_.children_pruned;
        }
      }
    }
    offerAll(batch);
    stats_.matings += count;
    if (progress && progress_interval > 0 && (begin + count) / progress_interval != begin / progress_interval &&
        begin + count < options_.matings) {
      progress(begin + count, options_.matings, best());
    }
  }
  if (progress) progress(options_.matings, options_.matings, best());
  std::vector<Individual> result;
  for (const auto& [cell, elite] : archive_.elites()) result.push_back(elite.individual);
  std::stable_sort(result.begin(), result.end(), [](const Individual& a, const Individual& b) {
    return a.score > b.score;
  });
  if (static_cast<int>(result.size()) > options_.population) result.resize(static_cast<std::size_t>(options_.population));
  return result;
}

std::string archiveCsv(const Archive& archive, const std::vector<std::string>& features,
                       const std::map<std::uint64_t, std::string>& set_ids) {
  std::vector<std::string> header{"cell"};
  for (const std::string& f : features) header.push_back(f + "_bin");
  for (const std::string& f : features) header.push_back(f);
  header.push_back("fitness_value");
  header.push_back("id");
  std::string text = csvLine(header) + "\n";
  for (const auto& [cell, elite] : archive.elites()) {
    std::vector<std::string> row{std::to_string(cell)};
    for (int bin : elite.bins) row.push_back(std::to_string(bin));
    for (double value : elite.features) row.push_back(formatNumber(value));
    row.push_back(formatNumber(elite.individual.value));
    const auto id = set_ids.find(elite.individual.grid.hash());
    row.push_back(id == set_ids.end() ? "" : id->second);
    text += csvLine(row) + "\n";
  }
  return text;
}

std::string archiveHeatMapSvg(const Archive& archive, const std::vector<std::string>& features,
                              const std::vector<FeatureRange>& ranges, const std::string& title) {
  const int bins = archive.bins();
  // The fittest elite per (first, second) bin pair.
  std::map<std::pair<int, int>, const Elite*> shown;
  double low = 1e300, high = -1e300;  // scores: fitter is higher whatever the fitness's direction
  double low_value = 0, high_value = 0;
  for (const auto& [cell, elite] : archive.elites()) {
    const std::pair<int, int> key{elite.bins[0], elite.bins[1]};
    auto& slot = shown[key];
    if (slot == nullptr || elite.individual.score > slot->individual.score) slot = &elite;
    if (elite.individual.score < low) low = elite.individual.score, low_value = elite.individual.value;
    if (elite.individual.score > high) high = elite.individual.score, high_value = elite.individual.value;
  }
  const int size = bins * kCellPixels;
  const int width = std::max(size + kMargin + 20, 480);  // room for the title and the caption
  const int height = size + kMargin + 40;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<rect x=\"0\" y=\"0\" width=\"" << width << "\" height=\"" << height << "\" fill=\"#ffffff\"/>\n"
      << "<text x=\"" << kMargin << "\" y=\"16\" font-size=\"13\">" << escapeMarkup(title) << "</text>\n";
  for (int bx = 0; bx < bins; ++bx) {
    for (int by = 0; by < bins; ++by) {
      const int x = kMargin + bx * kCellPixels;
      const int y = 30 + (bins - 1 - by) * kCellPixels;  // second feature grows upwards
      const auto found = shown.find({bx, by});
      std::string fill = "#dddddd";
      std::string tip = "empty";
      if (found != shown.end()) {
        const double share = high > low ? (found->second->individual.score - low) / (high - low) : 1.0;
        char colour[8];
        std::snprintf(colour, sizeof colour, "#%02x%02x%02x", 255 - static_cast<int>(75 * share),
                      static_cast<int>(235 - 215 * share), static_cast<int>(200 - 180 * share));
        fill = colour;
        tip = "fitness " + formatNumber(found->second->individual.value);
      }
      svg << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << kCellPixels - 1 << "\" height=\""
          << kCellPixels - 1 << "\" fill=\"" << fill << "\"><title>" << tip << "</title></rect>\n";
    }
  }
  const int axis_y = 30 + size;
  svg << "<text x=\"" << kMargin << "\" y=\"" << axis_y + 14 << "\">" << formatNumber(ranges[0].low) << "</text>\n"
      << "<text x=\"" << kMargin + size << "\" y=\"" << axis_y + 14 << "\" text-anchor=\"end\">"
      << formatNumber(ranges[0].high) << "</text>\n"
      << "<text x=\"" << kMargin + size / 2 << "\" y=\"" << axis_y + 28 << "\" text-anchor=\"middle\">"
      << escapeMarkup(features[0]) << "</text>\n"
      << "<text x=\"" << kMargin - 4 << "\" y=\"" << axis_y << "\" text-anchor=\"end\">"
      << formatNumber(ranges[1].low) << "</text>\n"
      << "<text x=\"" << kMargin - 4 << "\" y=\"40\" text-anchor=\"end\">" << formatNumber(ranges[1].high)
      << "</text>\n"
      << "<text transform=\"translate(14," << 30 + size / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
      << escapeMarkup(features[1]) << "</text>\n"
      << "<text x=\"" << kMargin << "\" y=\"" << axis_y + 42 << "\">" << archive.elites().size() << " of "
      << static_cast<long>(std::pow(bins, static_cast<double>(features.size())))
      << " cells filled; darker = fitter (fitness " << formatNumber(low_value) << " to " << formatNumber(high_value)
      << ")</text>\n</svg>\n";
  return svg.str();
}

}  // namespace generator
}  // namespace ppp
