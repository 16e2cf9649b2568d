#pragma once
// The topology changes of the enhancement (enhance.h, step 2), for where moving vertices alone
// cannot help: edge flips, collapses (valence-3 vertices, very short edges) and splits (a plane's
// fans of needles). Never across a feature, never away from the surface.

#include "enhance/surface_constraints.h"

#include "meshprep/core/mesh.h"

#include <cstddef>

namespace meshprep::detail {

/// A face with an angle this large is a cap: its apex lies nearly on its longest edge (CGAL's
/// remove_almost_degenerate_faces takes the same default).
inline constexpr double kCapAngleDeg = 160;

struct CleanupRules {
  double max_dihedral_deg = 20;  ///< the two faces after a flip must be this close to coplanar
  double max_deviation = 0;      ///< absolute distance to the reference a change may reach anyway
  double min_angle_cosine = 1;   ///< collapses only where a smallest angle is under this angle
};

/// One sweep over the interior non-feature edges: flip where the smaller of the two faces'
/// smallest angles grows, the new faces are nearly coplanar and keep the old pair's orientation,
/// no vertex drops under valence 3, the surface moves by at most max_deviation (the two diagonals'
/// midpoints apart along the normal), and the new diagonal's midpoint is no farther from the
/// reference than max(the old one's, max_deviation). The two old faces are not asked to be
/// coplanar: a cap (an angle near 180 degrees) has no reliable normal. Returns the flips made.
std::size_t flip_for_angles(TriMesh& mesh, const SurfaceConstraints& constraints, const CleanupRules& rules);

/// Flips the long edge of each cap (a face with an angle of at least kCapAngleDeg) where that
/// edge is a crease and the apex on no feature: the crease then runs through the apex instead
/// (SurfaceConstraints::flip_feature_through_apex). A cap's normal is noise, so its long edge may
/// look like a crease, which flip_for_angles never flips; a cap's largest angle caps the dihedral
/// angles of the tet TetGen builds on it (bull: a 171.6 degree cap, its tets stuck at 170
/// degrees). Made only where the surface moves by at most max_deviation (the apex is that close to
/// the long edge, and the new diagonal's midpoint is no farther from the reference than max(the
/// old one's, max_deviation)), the pair's smallest angle grows, no new angle reaches
/// kCapAngleDeg, the other face is no cap, the new faces face as it does, and no fold forms with
/// the faces around. Caps on no crease are left to flip_for_angles and the relocation: flipping
/// them too cost the camel its smallest angle (20.2 to 12.4 degrees). Returns the flips made.
std::size_t flip_caps(TriMesh& mesh, SurfaceConstraints& constraints, const CleanupRules& rules);

/// Removes Surface vertices where a smallest angle around them is under the target: each is
/// collapsed into the neighbour (kept where it is) that gives the best worst angle, when that beats
/// the old worst angle, no remaining face turns by more than 60 degrees, the new faces' centroids
/// stay within max(max_deviation, the old faces' largest centroid distance) of the reference, the
/// removed vertex is within max_deviation of a new face, every reference vertex under the fan that
/// was within max_deviation of it still is, and no feature edge is merged away (the faces that
/// vanish have none). This takes away valence-3 vertices
/// and the ends of very short edges, which moving vertices cannot mend. At most `budget` vertices;
/// the mesh is garbage-collected afterwards. Returns the vertices removed.
std::size_t collapse_for_angles(TriMesh& mesh, const SurfaceConstraints& constraints, const CleanupRules& rules,
                                std::size_t budget);

/// Splits, at its midpoint, the longest edge of each face under the target angle where the two
/// faces across that edge are coplanar (within 0.1 degrees: a CAD part's plane; a scan has no
/// such place), the edge is no feature, and the two faces' worst angle does not get worse. The
/// surface does not change; the relocation that follows moves the new vertex. This is for the
/// fans of needles that decimation leaves on a part's planes (fandisk at 30 %: a vertex of
/// valence 49), which no placement of their vertices can mend. At most `budget` splits (each adds
/// two faces). Returns the splits made.
std::size_t split_for_angles(TriMesh& mesh, SurfaceConstraints& constraints, const CleanupRules& rules,
                             std::size_t budget);

}  // namespace meshprep::detail
