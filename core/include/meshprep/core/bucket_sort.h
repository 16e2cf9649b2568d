#pragma once
/// \file bucket_sort.h
/// Sorting items that are ordered first by a vertex index: a counting sort into one run per
/// index, then each run sorted alone. Each run holds about a vertex's degree of items, so this
/// costs a fraction of one comparison sort of all of them (the face edges of topology and repair,
/// the faces of the weld's and the report's duplicate searches).

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace meshprep {

/// Sorts `items` by `less`, a strict order that compares `bucket(item)` (an index, any size: the
/// runs are sized by the largest met) before anything else. The items are moved to their runs in
/// place (each swap puts one item in its run for good: American flag sort), so a large array is
/// never held twice: the peak memory of topology and repair at millions of faces.
template <class T, class Bucket, class Less>
void sort_by_buckets(std::vector<T>& items, Bucket bucket, Less less) {
  std::size_t buckets = 0;
  for (const T& item : items) buckets = std::max(buckets, static_cast<std::size_t>(bucket(item)) + 1);
  std::vector<std::size_t> run_end(buckets + 1, 0);  // shifted by one: run_end[b + 1]
  for (const T& item : items) ++run_end[static_cast<std::size_t>(bucket(item)) + 1];
  for (std::size_t b = 1; b < run_end.size(); ++b) run_end[b] += run_end[b - 1];
  std::vector<std::size_t> next(run_end.begin(), run_end.end() - 1);  // each run's first unplaced slot
  for (std::size_t b = 0; b < buckets; ++b)
    while (next[b] < run_end[b + 1]) {
      const auto home = static_cast<std::size_t>(bucket(items[next[b]]));
      if (home == b) ++next[b];
      else std::swap(items[next[b]], items[next[home]++]);
    }
  for (std::size_t b = 0; b < buckets; ++b)
    std::sort(items.begin() + static_cast<std::ptrdiff_t>(run_end[b]),
              items.begin() + static_cast<std::ptrdiff_t>(run_end[b + 1]), less);
}

}  // namespace meshprep
