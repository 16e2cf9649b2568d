#pragma once
// Marks on the vertices of a mesh, cleared all at once: a round number per vertex instead of a
// flag, so starting a new set costs nothing (no clearing between queries on a hot path).

#include "meshprep/core/mesh.h"

#include <algorithm>
#include <vector>

namespace meshprep::detail {

class VertexMarks {
 public:
  explicit VertexMarks(std::size_t vertices) : round_of_(vertices, 0) {}

  /// Unmarks every vertex.
  void clear_all() {
    if (++round_ == 0) {  // the round number wrapped around: clear for real, once
      std::fill(round_of_.begin(), round_of_.end(), 0);
      round_ = 1;
    }
  }
  void mark(TriMesh::VertexHandle v) { round_of_[index(v)] = round_; }
  bool marked(TriMesh::VertexHandle v) const { return round_of_[index(v)] == round_; }

 private:
  static std::size_t index(TriMesh::VertexHandle v) { return static_cast<std::size_t>(v.idx()); }

  std::vector<unsigned> round_of_;
  unsigned round_ = 0;
};

}  // namespace meshprep::detail
