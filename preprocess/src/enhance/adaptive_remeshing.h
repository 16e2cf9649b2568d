#pragma once
// The remeshing at the head of the enhancement (enhance.h): new vertices where triangles are long,
// fewer where they crowd, so that a CAD export's needles, fans and strips become triangles the
// statistic can finish. Botsch & Kobbelt's isotropic remeshing ("A remeshing approach to
// multiresolution modeling", SGP 2004) with a sizing field (Dunyach et al., "Adaptive remeshing for
// real-time mesh deformation", Eurographics 2013): split edges longer than 4/3 of the target,
// collapse those shorter than 4/5, flip toward valence 6, relax tangentially, back onto the
// reference; features stay on their lines and corners where they are.

#include "enhance/sizing_field.h"
#include "enhance/surface_constraints.h"

#include "meshprep/core/mesh.h"

#include <cstddef>
#include <functional>

namespace meshprep::detail {

struct RemeshRules {
  std::size_t iterations = 5;  ///< Botsch & Kobbelt's five
  /// Absolute distance from the reference that no new edge midpoint or face centroid may exceed
  /// (and that the removed vertex of a collapse must be within of the new faces).
  double max_deviation = 0;
  double target_min_angle_deg = 20;  ///< a flip may not make a face's smallest angle worse than this and than it was
  std::size_t max_faces = 0;         ///< the splits stop at this many faces, collapses pending (0: no limit)
  std::function<bool()> out_of_time; ///< optional, asked before each iteration and every few hundred steps of its sweeps: true stops the remeshing there
};

struct RemeshCounts {
  std::size_t splits = 0, collapses = 0, flips = 0;
  bool stopped_at_max_faces = false;
  bool stopped_by_time = false;  ///< out_of_time said so: the mesh is half remeshed
};

/// Remeshes `mesh` to `sizing` (an edge's target is the mean of the field at its ends), every
/// vertex on the reference or its feature line. The mesh is garbage-collected at the end.
RemeshCounts remesh_to_sizing(TriMesh& mesh, SurfaceConstraints& constraints, const SizingField& sizing,
                              const RemeshRules& rules);

}  // namespace meshprep::detail
