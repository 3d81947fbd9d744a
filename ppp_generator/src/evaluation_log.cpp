#include "ppp_generator/evaluation_log.hpp"

#include "ppp_core/csv.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {
namespace generator {

EvaluationLog::EvaluationLog() : rows_(std::make_shared<Rows>()) { rows_->start = std::chrono::steady_clock::now(); }

Fitness EvaluationLog::wrap(Fitness fitness) const {
  if (!fitness.batch) return fitness;
  fitness.batch = [rows = rows_, scorer = std::move(fitness.batch)](const std::vector<const Problem*>& problems,
                                                                    const std::vector<const Grid*>& grids) {
    std::vector<FitnessScore> scores = scorer(problems, grids);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - rows->start).count();
    for (std::size_t i = 0; i < scores.size() && i < grids.size(); ++i) {
      rows->text += std::to_string(++rows->count) + "," + formatFixed(seconds, 3) + "," + formatNumber(scores[i].value) +
                    "," + formatNumber(scores[i].failure_rate) + "," + formatHex64(grids[i]->hash()) + "," +
                    std::to_string(scores[i].steps) + "\n";
    }
    return scores;
  };
  return fitness;
}

bool EvaluationLog::empty() const { return rows_->count == 0; }

std::string EvaluationLog::csv() const { return "evaluation,seconds,value,failure_rate,grid,steps\n" + rows_->text; }

std::string withoutSeconds(const std::string& evaluations_csv) {
  std::string kept;
  std::size_t begin = 0;
  while (begin < evaluations_csv.size()) {
    std::size_t end = evaluations_csv.find('\n', begin);
    if (end == std::string::npos) end = evaluations_csv.size();
    const std::string line = evaluations_csv.substr(begin, end - begin);
    const std::size_t first = line.find(',');
    const std::size_t second = first == std::string::npos ? first : line.find(',', first + 1);
    kept += (second == std::string::npos ? line : line.substr(0, first) + line.substr(second)) + "\n";
    begin = end + 1;
  }
  return kept;
}

}  // namespace generator
}  // namespace ppp
