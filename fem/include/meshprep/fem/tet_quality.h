#pragma once
/// \file tet_quality.h
/// Quality of a tetrahedral mesh: dihedral angles, radius-edge ratio (circumradius over the
/// shortest edge; sqrt(6)/4 = 0.612 for the regular tet, TetGen's -q bound is on this ratio),
/// Verdict's scaled Jacobian and aspect ratio, volumes, tets per region, the worst tets.
///
/// The two Verdict metrics follow the Verdict library (C. J. Stimpson, C. D. Ernst, P. Knupp,
/// P. P. Pebay, D. Thompson, "The Verdict Geometric Quality Library", SAND2007-1751, 2007; source
/// sandialabs/verdict, V_TetMetric.cpp: tet_scaled_jacobian, tet_aspect_ratio), so that the figures
/// are those ParaView's Mesh Quality filter and CUBIT show under the same names.

#include "meshprep/fem/tet_mesh.h"
#include "meshprep/quality/statistics.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

namespace meshprep {

/// Shape of one tetrahedron.
struct TetShape {
  double volume = 0;            ///< signed
  double min_dihedral_deg = 0;  ///< smallest of the six dihedral angles
  double max_dihedral_deg = 0;
  double radius_edge_ratio = 0;  ///< circumradius / shortest edge (+inf for a flat tet)
  /// Verdict's scaled Jacobian: sqrt(2) J / max(L_c, |J|), J = 6 x the signed volume and L_c the
  /// product of the three edge lengths at corner c; for a positive tet the smallest over the four
  /// corners of sqrt(2) J / L_c. In [-1, 1]: 1 for the regular tet, 0 for a flat one, negative
  /// for an inverted one (then the corner of least |J| / L_c, Verdict's choice); 0 when the corners
  /// coincide (Verdict: VERDICT_DBL_MAX).
  double scaled_jacobian = 0;
  /// Verdict's aspect ratio: longest edge / (2 sqrt(6) inradius), the inradius 3 |V| / (the faces'
  /// area). In [1, +inf): 1 for the regular tet, +inf for a flat one (Verdict: VERDICT_DBL_MAX);
  /// the same for both orientations. Not Verdict's radius ratio (circumradius / (3 inradius)).
  double aspect_ratio = 0;
};

/// Dihedral angles come from the faces' normals (interior angle = pi - angle between the outward
/// normals), so they are those of the geometric tet whatever its orientation; a flat tet has
/// angles of 0 and/or 180 degrees.
TetShape tet_shape(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3);

/// The shape of every tet of `mesh`, in order (computed in parallel; `cancelled` as analyze_tet_quality's).
/// \throws InvalidInput if a tet references a missing point.
std::vector<TetShape> tet_shapes(const TetMesh& mesh, const std::function<bool()>& cancelled = {});

/// Whether the tet (a, b, c, d) has a positive volume beyond doubt: (b - a) . ((c - a) x (d - a))
/// exceeds the bound on the rounding error of its own evaluation in doubles (Shewchuk 1997,
/// "Adaptive precision floating-point arithmetic and fast robust geometric predicates": orient3d's
/// error bound A, (7 + 56 eps) eps times the permanent of the differences). A tet that fails it is
/// flat to rounding (its corners in one plane as far as doubles can tell, whatever its size or its
/// place) or inverted: its stiffness matrix is singular, and no meshprep command writes it.
bool certainly_positive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The tets of `mesh` that are not certainly_positive, in order.
/// \pre every tet references existing points.
std::vector<std::size_t> flat_tets(const TetMesh& mesh);

/// "2 tets are flat or inverted (their volume is not positive beyond rounding); the first, tet 17,
/// at (x, y, z)", or empty when there are none.
std::string describe_flat_tets(const TetMesh& mesh);

/// One tet of a report's worst list.
struct WorstTet {
  std::size_t index = 0;       ///< in TetMesh::tets
  int region = 0;              ///< TetMesh::tet_regions[index]
  Vec3 centre = Vec3::Zero();  ///< the centroid: where to look
  TetShape shape;
};

/// The quality of a second-order mesh's tets (TetMesh::tet_edge_nodes), beyond that of their
/// corner tets (which the rest of TetQualityReport describes).
struct QuadraticTetQuality {
  /// Per tet, the smallest scaled Jacobian over its ten nodes: at each node and for each corner c,
  /// sqrt(2) det(d1, d2, d3) / (|d1| |d2| |d3|), d the derivatives of the tet's map along the three
  /// reference edges from c. 1 for the regular straight tet; for a straight tet Verdict's scaled
  /// Jacobian (TetShape); <= 0 where the map folds.
  Distribution min_scaled_jacobian{};
  /// Tets with det J <= 0 at one of their ten nodes, or whose corner tet is (volume <= 0).
  std::size_t nonpositive_jacobian_tets = 0;
  /// Tets with a mid-edge node off its edge's midpoint (by more than 1e-9 of the edge's length).
  std::size_t curved_tets = 0;
  std::vector<double> min_scaled_jacobian_per_tet;  ///< for histograms
};

/// How many worst tets analyze_tet_quality lists by default.
constexpr std::size_t kDefaultWorstTets = 10;

struct TetQualityReport {
  std::size_t points = 0;
  std::size_t tetrahedra = 0;
  double volume = 0;  ///< sum of the tets' signed volumes
  std::size_t inverted_tets = 0;  ///< volume <= 0
  Distribution min_dihedral_deg{}, max_dihedral_deg{}, radius_edge_ratio{};
  Distribution scaled_jacobian{}, aspect_ratio{};  ///< Verdict's (TetShape)
  double tets_min_dihedral_below_10 = 0;  ///< fraction
  std::map<int, std::size_t> tets_per_region;
  std::vector<double> min_dihedral_per_tet;     ///< for histograms
  std::vector<double> radius_edge_per_tet;      ///< for histograms
  std::vector<double> scaled_jacobian_per_tet;  ///< for histograms
  std::vector<double> aspect_ratio_per_tet;     ///< for histograms
  /// The tets with the smallest dihedral angles, smallest first (ties: lower index first).
  std::vector<WorstTet> worst_tets;
  /// Second-order meshes only; the dihedral angles and the other figures above are those of the
  /// corner tets.
  std::optional<QuadraticTetQuality> quadratic;
};

/// \throws InvalidInput if tet_regions' (or a second-order mesh's tet_edge_nodes') size differs
///         from tets' or a tet references a missing point: what every measure of the tets needs.
void check_tet_mesh_structure(const TetMesh& mesh);

/// Distributions ignore non-finite values (the radius-edge and aspect ratios of flat tets).
/// \param worst_tets how many of the worst tets to list (all when the mesh has fewer).
/// \param cancelled asked once per block of a few thousand tets, from any of the threads measuring
///        them (so it must be thread-safe); true: throws Cancelled.
/// \throws InvalidInput as check_tet_mesh_structure.
TetQualityReport analyze_tet_quality(const TetMesh& mesh, std::size_t worst_tets = kDefaultWorstTets,
                                     const std::function<bool()>& cancelled = {});

/// JSON keys: points, tetrahedra, volume, inverted_tets, min_dihedral_deg {min,mean,p5,p50,p95,max},
/// max_dihedral_deg {...}, radius_edge_ratio {...}, tets_min_dihedral_below_10, tets_per_region {"1": n},
/// scaled_jacobian {...}, aspect_ratio {...}, worst_tets [{index, region, centre [x,y,z],
/// min_dihedral_deg, max_dihedral_deg, radius_edge_ratio, scaled_jacobian, aspect_ratio}]; for a
/// second-order mesh also quadratic {min_scaled_jacobian {...}, nonpositive_jacobian_tets, curved_tets}.
nlohmann::ordered_json to_json(const TetQualityReport& report);

}  // namespace meshprep
