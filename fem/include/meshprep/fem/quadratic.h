#pragma once
/// \file quadratic.h
/// Second-order (10-node) tets from linear ones: a node in the middle of every edge, those of the
/// boundary placed on a reference surface (the surface the mesh approximates) where that keeps
/// every tet valid. Quadratic tets (Abaqus C3D10, Gmsh 11, VTK 24, dolfinx P2 geometry) do not
/// lock in bending as linear ones do, and a curved boundary follows a curved part more closely.
///
/// Validity: a curved tet is a cubic polynomial's worth of Jacobian determinants. A boundary
/// edge's node is placed on the reference only if, for every tet around the edge (with the
/// nodes already placed), the smallest Bezier coefficient of det J, a lower bound of det J over
/// the whole tet (not only at its ten nodes), stays at or above kMinJacobianRatio times the
/// straight tet's det J; else the edge stays straight and is counted. A straight second-order
/// tet has det J equal to its straight value everywhere, so the result never has a tet with a
/// non-positive Jacobian where the linear mesh had none.

#include "meshprep/core/mesh.h"
#include "meshprep/core/taken_back.h"
#include "meshprep/fem/tet_mesh.h"

#include <nlohmann/json.hpp>

namespace meshprep {

/// The least det J a curved tet may have anywhere, relative to its straight tet's (unit-free: both
/// scale as length^3). 0.1 is the bound below which Gmsh's high-order optimiser treats an element
/// as one to mend (Mesh.HighOrderThresholdMin, 0.1 by default in Gmsh 4.8, on the same ratio
/// min det J / straight det J): curving never makes an element Gmsh would call bad.
inline constexpr double kMinJacobianRatio = 0.1;

/// A boundary node placed at the reference point r, moved by d from the edge's midpoint, must
/// have the tets' boundary no nearer to r than kMutualClosest * d: r is then the nearest
/// reference point of this part of the boundary, not of another part the reference also
/// passes near (the top of a terrain seen from the block's sides and base, the far wall of a
/// thin part).
inline constexpr double kMutualClosest = 0.5;

/// The element order of the tets a command writes: 1 linear (4-node tets), 2 second-order
/// (10-node tets, make_quadratic after any improvement, which moves linear tets only).
struct ElementOrderParams {
  std::size_t order = 1;
};

/// A midpoint this near the reference, relative to its edge's length, is on it: round-off of a
/// linear boundary that lies in the reference's own facets (TetGen's splits of the input's
/// triangles), where the mutual-closest test would compare distances that are noise.
inline constexpr double kOnReference = 1e-9;

struct QuadraticResult {
  std::size_t edges = 0;           ///< mid-edge nodes made: the mesh's edges
  std::size_t boundary_edges = 0;  ///< edges of boundary faces (faces of one tet)
  std::size_t curved_edges = 0;    ///< boundary edges whose node was placed on the reference
  /// Boundary edges whose midpoint is on the reference already (within kOnReference of the edge's
  /// length): left as they are, neither curved nor counted as kept straight.
  std::size_t on_reference = 0;
  std::size_t straight_inverting = 0;      ///< kept straight: curving took det J under the bound
  std::size_t straight_off_reference = 0;  ///< kept straight: the nearest reference point belongs to another part
  /// The largest distance of a placed node from its edge's midpoint, over the edge's length.
  double max_offset_relative = 0;
  double min_scaled_jacobian = 0;  ///< of the second-order tets, over their ten nodes (tet_quality.h)
  /// Tets whose det J is not positive somewhere (the Bezier bound <= 0): 0 unless a corner tet
  /// already was flat or inverted.
  std::size_t nonpositive_jacobian_tets = 0;
  double seconds = 0;
  std::vector<TakenBack> taken_back;  ///< the edges kept straight because curving would fold a tet
};

/// Makes `mesh` second-order in place: one new point per edge, appended to mesh.points (in the
/// order of the edges' sorted corner pairs), and mesh.tet_edge_nodes. Interior edges and
/// interfaces get their midpoint. Boundary edges get the closest point of `reference` when it is
/// given and the rules above allow, else their midpoint. Nothing depends on units.
/// \param reference the surface the boundary approximates (may be null: every edge straight);
///        it needs no particular orientation.
/// \throws InvalidInput if the mesh is already second-order, has no tets, or a tet references a
///         missing point.
QuadraticResult make_quadratic(TetMesh& mesh, const TriangleSoup* reference = nullptr);

/// The boundary of a second-order mesh (its faces of one tet) as a fine triangle soup: each face's
/// quadratic map sampled on a lattice of `subdivisions` steps per edge (subdivisions^2 triangles
/// per face, their corners on the curved face), for distances to the reference. A linear mesh
/// gives its flat faces likewise subdivided.
/// \throws InvalidInput if subdivisions < 1.
TriangleSoup quadratic_boundary(const TetMesh& mesh, int subdivisions);

/// The figures, for reports: keys as the struct's members.
nlohmann::ordered_json to_json(const QuadraticResult& result);

}  // namespace meshprep
