#pragma once
/// \file readiness.h
/// Is a surface ready for tetrahedralisation? TetGen needs a closed, manifold, consistently
/// oriented surface without degenerate or duplicate faces and without self-intersections; when it
/// gets anything else it fails with a bare code (or, on open surfaces, "succeeds" with zero tets).
/// This check names each problem, how many, the first offending faces and what to do.

#include "meshprep/core/mesh.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace meshprep {

struct ReadinessProblem {
  /// "welded", "closed", "manifold", "oriented", "degenerate_faces", "duplicate_faces", "self_intersections"
  std::string check;
  std::size_t count = 0;  ///< how many edges/vertices/faces/pairs
  std::string what;    ///< one line: the problem in words with the count
  std::string hint;    ///< what to do about it
  std::vector<std::size_t> faces;  ///< the first offending face indices (at most 100)
};

struct Readiness {
  bool ready() const { return problems.empty(); }
  std::vector<ReadinessProblem> problems;
  bool inward_oriented = false;  ///< consistently oriented but enclosing negative volume (not a problem: flipped)
  std::size_t isolated_vertices = 0;  ///< points no face uses (not a problem: plc_from_surface leaves them out)
};

/// Check `surface` for tetrahedralisation. Vertices at exactly the same place (a file that splits
/// its vertices) are one problem, "welded"; the other checks then describe the welded surface.
/// A caller that has just searched this very surface for self-intersections and found none (the
/// repair) says so with `known_free_of_self_intersections`: the search, the check's costliest
/// part, is then skipped, unless vertices had to be welded (which changes what touches).
Readiness check_fem_readiness(const TriangleSoup& surface, bool known_free_of_self_intersections = false);

/// The offending faces of every problem as a small soup (their vertices renumbered), to open
/// next to the input in a viewer.
TriangleSoup diagnosis_mesh(const TriangleSoup& surface, const Readiness& readiness);

/// {"ready": bool, "problems": [{check, count, what, hint, faces}]}.
nlohmann::ordered_json to_json(const Readiness& readiness);

}  // namespace meshprep
