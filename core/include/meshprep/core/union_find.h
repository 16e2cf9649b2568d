#pragma once
/// \file union_find.h
/// Disjoint sets of indices (a forest with path halving); a set's root is its lowest index.

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace meshprep::detail {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::uint32_t{0}); }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  /// Joins the sets of a and b; false if they were one already.
  bool unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[a < b ? b : a] = a < b ? a : b;
    return true;
  }

 private:
  std::vector<std::uint32_t> parent_;
};

}  // namespace meshprep::detail
