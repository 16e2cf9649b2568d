#pragma once
/// \file tetrahedralize.h
/// Quality tetrahedralisation of a closed surface with TetGen (Debian's libtet 1.5), isolated in
/// a child process so that a TetGen crash or abort becomes an error, never the end of the caller.

#include "meshprep/core/errors.h"
#include "meshprep/core/mesh.h"
#include "meshprep/core/size_field.h"
#include "meshprep/fem/tet_mesh.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace meshprep {

struct TetParams {
  double radius_edge = 1.414;  ///< TetGen -q bound on circumradius / shortest edge (in [1, 100]; 0 = no refinement)
  double min_dihedral_deg = 0;  ///< TetGen -q/DEG target for the smallest dihedral angle, in [0, 30] (0 = TetGen's default)
  double max_volume = 0;        ///< TetGen -a: largest tet volume, absolute, finite (0 = no bound)
  double max_volume_relative = 0;  ///< same, as a fraction of the enclosed volume, in [0, 1] (0 = no bound)
  bool keep_surface = false;    ///< TetGen -Y: the boundary keeps exactly the input triangles
  /// The edge length to aim at (TetGen -m, its sizes at the PLC's points: kTetgenSizePerLength x
  /// h there, interpolated between them); null: none.
  std::shared_ptr<const SizeField> size_field;
  /// Asked every 50 ms while TetGen runs; true stops it (tetrahedralize_plc throws Cancelled).
  std::function<bool()> cancelled;
};

/// A piecewise-linear complex for TetGen: planar polygonal facets with boundary tags.
struct SurfacePlc {
  std::vector<Vec3> points;
  std::vector<std::vector<std::uint32_t>> facets;  ///< each a planar polygon, 3 or more corners
  std::vector<int> tags;                           ///< one per facet, >= 1
  TagNames tag_names;  ///< the names of the tags (the surface's patches), given to the tets' boundary
  /// A point inside each void (TetGen's hole list): the region around it gets no tets.
  std::vector<Vec3> holes;
};

/// A TetGen failure, with TetGen's code (1 memory, 2 internal, 3 self-intersection, 4 tiny
/// feature, 5 facets too close, 10 input; 0 no tets; -1 crashed) and a hint in the message.
class TetgenError : public Error {
 public:
  TetgenError(int code, const std::string& message) : Error(message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

/// TetGen's -m splits a tet while half the longest edge at one of its vertices exceeds that
/// vertex's size (tetgen 1.5.1, checktet4split), so the sizes given are this fraction of the
/// target length h: the split stops once edges are under 2 x share x h. Measured on the shared CAD
/// parts with --size (bench/RESULTS.md, "Size field"), a share of 1/2 left the median edge at
/// 0.7 h; this one centres it on h.
inline constexpr double kTetgenSizePerLength = 0.75;

/// Checks every field of `params` against its range above; NaN and infinities are never in range.
/// A radius-edge bound under 1 is refused: TetGen's refinement need not end below it (0.5 ran for
/// ever, issue 30). \throws InvalidInput "tetrahedralize: <field> must be ..., not <value>".
void check_tet_params(const TetParams& params);

/// The volume the PLC encloses (each facet fanned from its first corner; a void's wall, facing
/// into it, counts negative).
double plc_volume(const SurfacePlc& plc);

/// How far the tets' volume is from the PLC's, relative to it: (tets - plc) / plc. To rounding
/// (1e-12) with TetParams::keep_surface; without it, TetGen treats neighbouring facets within 0.1
/// degrees of flat as one facet (its -p tolerance, 179.9 degrees) and may retriangulate across
/// their edge, which moves the boundary off a curved surface's nearly flat facets (1e-9 to 1e-6 of
/// the volume on the shared CAD parts). Refusing it (TetGen's -p180) would keep every edge, at up
/// to 2.6 times the tets (fandisk).
double volume_change_relative(const SurfacePlc& plc, const TetMesh& tets);

/// Above this |volume_change_relative| the boundary moved beyond the rounding of the two sums.
inline constexpr double kVolumeKeptRelative = 1e-12;

/// "the tets' volume differs from the surface's by 1.65e-06 of it: TetGen ... (--keep-surface keeps
/// it)" when |change| > kVolumeKeptRelative; empty otherwise.
std::string volume_change_note(double change);

/// Tetrahedralise a PLC (no readiness check: the caller vouches for it).
/// \throws TetgenError; InvalidInput for params out of range (check_tet_params); Cancelled when
/// params.cancelled said so.
TetMesh tetrahedralize_plc(const SurfacePlc& plc, const TetParams& params);

/// The TetGen switches for `params` ("pzQ" + q, a, Y), given the enclosed volume.
/// \throws InvalidInput for params out of range (check_tet_params).
std::string tetgen_switches(const TetParams& params, double enclosed_volume);

/// The PLC of a closed triangle surface, each facet tagged with its face's patch (and the patches'
/// names), or with `tag` when the surface has no patches. Points no face uses are left
/// out (TetGen would make those inside the volume tet vertices and drop the others); the others
/// keep their order. A closed component enclosing negative volume faces inwards: the wall of a
/// void (repair's keep_cavities), which gets a hole point just inside it.
SurfacePlc plc_from_surface(const TriangleSoup& surface, int tag = 1);

}  // namespace meshprep
