#pragma once
// The bending energy of an edge's local spline (the volume spline over the union of its end
// points' 1-rings, at the sliding-landmark optimum: sliding_landmarks.h), and the scales every
// collapse cost is measured in.

#include "rbf/collapse_energy_block.h"
#include "simplify/vertex_marks.h"

#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/simplify/simplify.h"

#include <limits>
#include <vector>

namespace meshprep::detail {

// Gathers the centres of an edge's local spline: its end points (indices 0 and 1), then the union
// of their 1-rings, de-duplicated with vertex marks (no search).
class RingUnion {
 public:
  explicit RingUnion(const TriMesh& mesh) : mesh_(mesh), seen_(mesh.n_vertices()) {}

  // Returns the count, or 0 if there are more than kMaxBlockCentres.
  int gather(TriMesh::VertexHandle a, TriMesh::VertexHandle b, Vec3* centres) {
    seen_.clear_all();
    int n = 0;
    for (const TriMesh::VertexHandle end : {a, b}) {
      seen_.mark(end);
      centres[n++] = to_eigen(mesh_.point(end));
    }
    for (const TriMesh::VertexHandle end : {a, b}) {
      for (const TriMesh::VertexHandle w : mesh_.vv_range(end)) {
        if (seen_.marked(w)) continue;
        if (n == kMaxBlockCentres) return 0;
        seen_.mark(w);
        centres[n++] = to_eigen(mesh_.point(w));
      }
    }
    return n;
  }

 private:
  const TriMesh& mesh_;
  VertexMarks seen_;
};

// J(s*) of the edge's optimal point on its line (sliding_landmarks.h); NaN when the spline is
// undefined (collinear or coincident centres, or an oversized ring).
struct EdgeEnergy {
  double energy = std::numeric_limits<double>::quiet_NaN();
  Vec3 point = Vec3::Zero();
};

EdgeEnergy edge_energy(RingUnion& rings, TriMesh::VertexHandle a, TriMesh::VertexHandle b,
                       std::vector<Vec3>* neighbourhood);

/// Scales measured once on the input, so every cost is dimensionless.
struct CollapseScales {
  double edge_length = 1;     ///< median edge length
  double energy_per_length = 1;  ///< median J / |e| over a sample of edges (Bending)
  double diagonal = 1;        ///< bounding-box diagonal
};

CollapseScales measure_scales(const TriMesh& mesh, CollapseCost cost);

}  // namespace meshprep::detail
