#pragma once

// The five-taxon UPGMA example shared by the taxonomy, Newick and HTML tests.

#include <Eigen/Core>

#include "ppp_generator/taxonomy.hpp"

namespace ppp::generator::test {

/// The classic five-taxon UPGMA example (5S ribosomal RNA of a = Bacillus subtilis, b = B. stearothermophilus,
/// c = Lactobacillus viridescens, d = Acholeplasma modicum, e = Micrococcus luteus):
///
///        a   b   c   d   e
///   a    0  17  21  31  23
///   b   17   0  30  34  21
///   c   21  30   0  28  39
///   d   31  34  28   0  43
///   e   23  21  39  43   0
///
/// Worked by hand:
///   1. smallest is d(a,b) = 17: node 5 = (a,b), height 8.5.
///      d(5,c) = (21+30)/2 = 25.5, d(5,d) = (31+34)/2 = 32.5, d(5,e) = (23+21)/2 = 22.
///   2. smallest is d(5,e) = 22: node 6 = ((a,b),e), height 11.
///      d(6,c) = (2*25.5 + 39)/3 = 30, d(6,d) = (2*32.5 + 43)/3 = 36.
///   3. smallest is d(c,d) = 28: node 7 = (c,d), height 14.
///      d(6,7) = (d(6,c) + d(6,d))/2 = (30 + 36)/2 = 33 (= the mean of the six leaf-pair distances, 198/6).
///   4. node 8 = (6,7), height 16.5, the root.
/// Branch lengths: a, b 8.5; (a,b) 2.5; e 11; ((a,b),e) 5.5; c, d 14; (c,d) 2.5.
inline Eigen::MatrixXd handDistances() {
  Eigen::MatrixXd d(5, 5);
  d << 0, 17, 21, 31, 23,  //
      17, 0, 30, 34, 21,   //
      21, 30, 0, 28, 39,   //
      31, 34, 28, 0, 43,   //
      23, 21, 39, 43, 0;
  return d;
}

/// UPGMA of handDistances(): merges (a,b) at 8.5, ((a,b),e) at 11, (c,d) at 14, root 16.5.
inline Tree handTree() { return upgma(handDistances()); }

}  // namespace ppp::generator::test
