#include "ppp_generator/signature_archive.hpp"

#include <algorithm>
#include <iterator>
#include <set>

#include "ppp_core/csv.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {
namespace generator {

namespace {

constexpr std::size_t kParts = 6;  // HOW, gG, sS, tT, wOeE, the goal's shape

std::vector<std::string> partsOf(const std::string& signature) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t slash = signature.find('/', begin);
    parts.push_back(signature.substr(begin, slash == std::string::npos ? std::string::npos : slash - begin));
    if (slash == std::string::npos) break;
    begin = slash + 1;
  }
  parts.resize(kParts);  // a signature without the goal's shape has an empty sixth part
  return parts;
}

}  // namespace

long maxSignatureElites(const GeneratorOptions& options) {
  const double cells = static_cast<double>(options.width) * options.height;
  return std::max(0L, static_cast<long>(kMaxPoolCells / cells) - options.population);
}

int signatureDistance(const std::string& a, const std::string& b) {
  const std::vector<std::string> pa = partsOf(a), pb = partsOf(b);
  int differing = 0;
  for (std::size_t i = 0; i < kParts; ++i) differing += pa[i] != pb[i] ? 1 : 0;
  return differing;
}

long SignatureArchive::timesSeen(const Individual& individual) const {
  long fewest = -1;
  for (const auto& shown : individual.signatures) {
    const auto it = entries_.find(shown.first);
    const long seen = it == entries_.end() ? 0 : it->second.seen;
    if (fewest < 0 || seen < fewest) fewest = seen;
  }
  return fewest;
}

bool SignatureArchive::offer(const Individual& individual) {
  if (individual.signatures.empty() && (!has_passed_ || individual.score > passed_.score)) {
    passed_ = individual;
    has_passed_ = true;
  }
  bool novel = false;
  for (const auto& shown : individual.signatures) {
    const std::string& signature = shown.first;
    auto it = entries_.find(signature);
    if (it == entries_.end()) {
      if (static_cast<long>(entries_.size()) >= max_entries_) {
        ++dropped_;
        continue;
      }
      it = entries_.emplace(signature, Entry{individual, offers_, 0}).first;
      novel = true;
    } else if (individual.score > it->second.elite.score) {
      it->second.elite = individual;
    }
    ++it->second.seen;
  }
  ++offers_;
  return novel;
}

const Individual* SignatureArchive::randomElite(Rng* rng) const {
  if (entries_.empty() && !has_passed_) return nullptr;
  // Each signature weighs 1 / (PPPs that showed it): a failure the search meets seldom is bred from as often, over
  // the hunt, as a common one; the passed PPP weighs as a signature seen once.
  double total = has_passed_ ? 1.0 : 0.0;
  for (const auto& entry : entries_) total += 1.0 / static_cast<double>(std::max(1L, entry.second.seen));
  double drawn = rng->uniform01() * total;
  for (const auto& entry : entries_) {
    drawn -= 1.0 / static_cast<double>(std::max(1L, entry.second.seen));
    if (drawn < 0) return &entry.second.elite;
  }
  return has_passed_ ? &passed_ : &entries_.rbegin()->second.elite;
}

std::vector<Individual> SignatureArchive::diverseSet(int size, const std::vector<Individual>& pool) const {
  std::vector<const std::pair<const std::string, Entry>*> left;
  for (const auto& entry : entries_) left.push_back(&entry);
  std::vector<Individual> set;
  std::set<std::uint64_t> taken;  // grid hashes
  std::vector<std::string> covered;
  // Of entries as far from the covered ones: the fitter, then the rarer (a fault the search meets seldom), then
  // the one found first.
  const auto fitter = [](const Entry& a, const Entry& b) {
    if (a.elite.score != b.elite.score) return a.elite.score > b.elite.score;
    return a.seen != b.seen ? a.seen < b.seen : a.found < b.found;
  };
  while (static_cast<int>(set.size()) < size && !left.empty()) {
    // The entry farthest from the signatures covered (every entry is as far as can be from none).
    std::size_t best = 0;
    int best_distance = -1;
    for (std::size_t i = 0; i < left.size(); ++i) {
      int distance = static_cast<int>(kParts);
      for (const std::string& c : covered) distance = std::min(distance, signatureDistance(left[i]->first, c));
      if (distance > best_distance || (distance == best_distance && fitter(left[i]->second, left[best]->second))) {
        best = i;
        best_distance = distance;
      }
    }
    const Individual& elite = left[best]->second.elite;
    covered.push_back(left[best]->first);
    left.erase(left.begin() + static_cast<std::ptrdiff_t>(best));
    if (taken.insert(elite.grid_hash).second) set.push_back(elite);
  }
  std::vector<const Individual*> rest;
  for (const Individual& member : pool) rest.push_back(&member);
  std::stable_sort(rest.begin(), rest.end(), [](const Individual* a, const Individual* b) { return a->score > b->score; });
  for (const Individual* member : rest) {
    if (static_cast<int>(set.size()) >= size) break;
    if (taken.insert(member->grid_hash).second) set.push_back(*member);
  }
  return set;
}

std::string SignatureArchive::csv(const std::map<std::uint64_t, std::string>& set_ids) const {
  std::string text = "signature,found,seen,value,problem\n";
  for (const auto& [signature, entry] : entries_) {
    const auto id = set_ids.find(entry.elite.grid_hash);
    text += csvLine({signature, std::to_string(entry.found), std::to_string(entry.seen), formatNumber(entry.elite.value),
                     id == set_ids.end() ? "" : id->second}) +
            "\n";
  }
  return text;
}

}  // namespace generator
}  // namespace ppp
