#pragma once

#include <map>
#include <string>
#include <vector>

#include "ppp_generator/breeder.hpp"

namespace ppp {
namespace generator {

/// The file of a set directory that lists a signature archive (SignatureArchive::csv()).
constexpr const char* kSignatureArchiveFile = "signatures.csv";

/// A hunt's archive of failures keyed by failure signature (docs/reference/signatures.md): for each signature any
/// scored PPP's runs showed, the fittest PPP that showed it (the first of equals). The hunt's set is drawn from it
/// (diverseSet()), so one copy of each way the panel fails outranks further copies of a known one.
class SignatureArchive {
 public:
  /// One signature's entry.
  struct Entry {
    Individual elite;   ///< The fittest PPP whose runs showed the signature.
    long found = 0;     ///< The offer (0-based, in offer order) that first showed it.
    long seen = 0;      ///< PPPs offered that showed it.
  };

  /// An archive of no entries.
  SignatureArchive() = default;
  /// An archive of at most `max_entries` signatures (one more new signature is counted in dropped(), not kept).
  explicit SignatureArchive(long max_entries) : max_entries_(max_entries) {}

  /// Offers a scored PPP; true when one of its signatures was new to the archive (and kept).
  bool offer(const Individual& individual);
  /// New signatures not kept: the archive was full.
  long dropped() const { return dropped_; }
  /// The elite of an entry or the passed PPP kept (passed()), drawn with weight 1 / (PPPs that showed the entry's
  /// signature), the passed PPP as a signature seen once: the masked faults' failures, which a search meets
  /// seldom, are bred from as often as the common ones; nullptr (no draw made) when it holds neither.
  const Individual* randomElite(Rng* rng) const;
  /// The fittest PPP offered that showed no failure (the first of equals): the hardest one the panel still
  /// passes, from which a search climbs towards failures the easier ones hide; nullptr before the first.
  const Individual* passed() const { return has_passed_ ? &passed_ : nullptr; }
  /// How often the archive has seen `individual`'s rarest signature: the `seen` of the least seen one among its
  /// signatures (0 for one it does not hold), or -1 for a PPP showing none (a tournament ranks it behind).
  long timesSeen(const Individual& individual) const;
  /// The entries by signature.
  const std::map<std::string, Entry>& entries() const { return entries_; }

  /// Up to `size` distinct PPPs: first the fittest elite (the first found of equals), then again and again the
  /// elite whose signature differs in the most parts (HOW, gG, sS, tT, wOeE, the goal's shape) from the nearest
  /// signature already taken (ties: fitter, then found first); then, while there is room, the fittest members of
  /// `pool` not taken.
  std::vector<Individual> diverseSet(int size, const std::vector<Individual>& pool) const;

  /// The archive as CSV: signature, found, seen, the elite's value and, when it is in the set (`set_ids`, keyed by
  /// grid hash), its id there; in signature order.
  std::string csv(const std::map<std::uint64_t, std::string>& set_ids) const;

 private:
  std::map<std::string, Entry> entries_;
  Individual passed_;
  bool has_passed_ = false;
  long max_entries_ = 0;
  long offers_ = 0;
  long dropped_ = 0;
};

/// The most signatures a hunt's archive keeps: as many PPPs as fit beside the pool in kMaxPoolCells grid cells.
long maxSignatureElites(const GeneratorOptions& options);

/// The number of parts (HOW, gG, sS, tT, wOeE, the goal's shape, which a signature may lack) in which two
/// signatures differ: 0 for equal ones, 6 at most.
int signatureDistance(const std::string& a, const std::string& b);

}  // namespace generator
}  // namespace ppp
