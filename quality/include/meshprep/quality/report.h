#pragma once
/// \file report.h
/// The quality report of a surface mesh: topology, geometry, per-face shape, optional distance to
/// a reference. It measures, it never modifies. Serialised by to_json (report_json.h) and the
/// writers in report_writers.h; the JSON keys are the field names below.

#include "meshprep/core/mesh.h"
#include "meshprep/core/soup_view.h"
#include "meshprep/quality/statistics.h"
#include "meshprep/quality/triangle_metrics.h"

#include <optional>
#include <string>
#include <vector>

namespace meshprep {

/// Options of analyze_quality.
struct QualityParams {
  std::size_t worst_faces = 10;              ///< how many of the worst faces (by radius ratio) to list
  std::size_t self_intersection_cap = 100000;  ///< stop counting intersecting pairs beyond this; 0 = skip the test
  std::size_t distance_samples = 1000000;    ///< area-weighted samples per direction for reference distances
  unsigned seed = 12345;                     ///< sampler seed (the result is deterministic for a seed)
};

/// Symmetric distances between a mesh and a reference surface (absolute units and relative to the
/// reference's bounding-box diagonal). Computed from dense area-weighted sampling of both
/// surfaces plus all vertices, each point's exact distance to the other surface through a BVH.
struct ReferenceComparison {
  std::string path;
  double hausdorff = 0;           ///< max over both directions
  double hausdorff_relative = 0;  ///< hausdorff / reference bbox diagonal
  double rms_relative = 0;        ///< sqrt of the mean of both directions' mean squared distance, / diagonal
  double mean_relative = 0;       ///< mean of both directions' mean distance, / diagonal
  double reference_bbox_diagonal = 0;
  std::optional<double> volume_change_percent;  ///< when both surfaces are closed
  std::size_t samples = 0;        ///< sample points per direction (random + vertices + refinement)
};

/// One of the worst faces, for the report.
struct WorstFace {
  std::size_t index = 0;
  TriangleShape shape;
};

struct QualityReport {
  std::string path;  ///< the file measured (may be empty for an in-memory mesh)

  // Counts and topology (computed on the soup as written, see topology.h)
  std::size_t vertices = 0;           ///< vertices referenced by a face
  std::size_t isolated_vertices = 0;  ///< points of the file that no face uses
  std::size_t faces = 0;
  std::size_t edges = 0;
  std::size_t components = 0;
  std::size_t border_edges = 0;
  std::size_t boundary_loops = 0;
  std::size_t non_manifold_edges = 0;
  std::size_t non_manifold_vertices = 0;
  bool closed = false;
  bool manifold = false;
  bool oriented = false;
  long long euler_characteristic = 0;
  std::optional<long long> genus;  ///< total genus of the closed components; empty if not closed and manifold
  std::size_t degenerate_faces = 0;
  std::size_t duplicate_faces = 0;
  std::size_t self_intersections = 0;  ///< intersecting non-adjacent face pairs
  bool self_intersections_capped = false;
  std::vector<std::pair<std::size_t, std::size_t>> self_intersecting_pairs;  ///< the first pairs found

  // Geometry
  double area = 0;
  std::optional<double> volume;  ///< signed (positive for outward normals); closed, oriented meshes only
  double bbox_diagonal = 0;
  Vec3 bbox_min = Vec3::Zero(), bbox_max = Vec3::Zero();

  // Per-face shape: distributions over the non-degenerate faces
  Distribution radius_ratio{}, aspect_ratio{}, min_angle_deg{}, max_angle_deg{}, area_distribution{};
  double faces_min_angle_below_20 = 0;  ///< fraction of non-degenerate faces
  double faces_min_angle_below_10 = 0;
  double faces_radius_ratio_above_2 = 0;
  std::vector<WorstFace> worst_faces;  ///< worst first (degenerate faces first of all)

  std::vector<TriangleShape> face_shapes;  ///< per face, in face order (for CSV, VTK, histograms)

  std::optional<ReferenceComparison> reference;

  double time_seconds = 0;  ///< time spent in analyze_quality
};

/// Measure a surface (a TriangleSoup, or a TriMesh through MeshSoupView). If `reference` is given,
/// also the symmetric distances to it.
QualityReport analyze_quality(const SoupView& soup, const QualityParams& params = {},
                              const TriangleSoup* reference = nullptr);

/// The face pairs by which a stage's `output` intersects itself beyond the `input_pairs` of its
/// input: what every surface stage guarantees to be 0 (the commands then write nothing, the
/// pipeline stops). An input's own intersections are not the stage's to remove.
std::size_t new_self_intersections(const QualityReport& output, std::size_t input_pairs);

}  // namespace meshprep
