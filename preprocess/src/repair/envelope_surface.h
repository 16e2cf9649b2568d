#pragma once
// Repair's second route (repair.h): the surface of the solid a soup encloses, rebuilt on a grid,
// for the soups the exact cut cannot mend.

#include "meshprep/core/mesh.h"

#include <cstddef>
#include <functional>

namespace meshprep::detail {

struct EnvelopeSurface {
  TriangleSoup surface;       ///< closed, manifold, no two faces crossing
  double cell = 0;            ///< the grid's spacing, in the soup's units
  std::size_t grid_points = 0;
  std::size_t relabelled_specks = 0;  ///< grid points of a group smaller than a cube given the other label
};

/// The boundary of the region where the soup's generalised winding number (winding_number.h) is
/// at least one half: inside for overlapping, nested, folded or holed soups alike (Jacobson et al.
/// 2013), as fTetWild keeps its cells (Hu et al. 2020). The number is taken at the points of a
/// grid `cells` cells across the soup's longest side, one cell of margin around, each cube split
/// into six tetrahedra along its main diagonal (Kuhn's split, the same in every cube, so neighbours
/// share their faces' diagonals); each tetrahedron with corners on both sides gives one triangle
/// or two (marching tetrahedra). That surface is closed and manifold whatever the labels, and no
/// two of its faces cross: each lies in its own tetrahedron. Its vertices are placed on the
/// soup: where the grid edge crosses the face past which the number drops under one half (a
/// crossing found exactly along the edge), or, in a hole's span, where the number falls to one
/// half; always strictly inside the edge, which keeps the faces in their tetrahedra. Groups of
/// grid points smaller than a cube take the other label first (a speck of solid in a wedge thinner
/// than a cell). The surface has several faces per cell it crosses, many tiny (where the soup
/// passes close to a grid point): compose/repair_solid.h simplifies it. The patches, if any, go to each new face from the soup's face nearest its
/// centre. The grid is shifted off the soup's bounding box by irrational fractions of a cell, so
/// that a part's axis-aligned faces do not hold grid points. `poll` is called between the steps.
EnvelopeSurface envelope_surface(const TriangleSoup& soup, std::size_t cells, const std::function<void()>& poll);

}  // namespace meshprep::detail
