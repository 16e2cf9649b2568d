#pragma once
/// \file simplify.h
/// Reducing a triangle mesh to a target size by iterative edge collapse.
///
/// Status: only the baseline cost is in so far — OpenMesh's own Decimater with ModQuadric
/// (Garland-Heckbert quadrics) and ModNormalFlipping, the peer every other cost is measured
/// against. The paper's bending-energy cost (Section 4) builds on sliding_landmarks.h and
/// local_height_map.h and comes next.

#include "meshprep/core/mesh.h"

namespace meshprep {

enum class CollapseCost {
  Quadric,  ///< OpenMesh Decimater + ModQuadric + ModNormalFlipping (baseline)
};

struct SimplifyParams {
  double keep_ratio = 0.1;        ///< fraction of the faces kept, (0, 1]; ignored if target_faces > 0
  std::size_t target_faces = 0;   ///< absolute target; 0 = use keep_ratio
  CollapseCost cost = CollapseCost::Quadric;
};

struct SimplifyResult {
  std::size_t faces_before = 0, faces_after = 0, target_faces = 0;
  bool reached_target = false;  ///< faces_after within 1 % of the target
  double seconds = 0;           ///< the decimation itself
};

/// Simplify `mesh` in place (garbage-collected on return). Topology-changing collapses are
/// refused by OpenMesh's link-condition test, so a closed manifold stays closed and manifold.
/// \throws InvalidInput if the mesh has no faces or the ratio is outside (0, 1].
SimplifyResult simplify(TriMesh& mesh, const SimplifyParams& params = {});

}  // namespace meshprep
