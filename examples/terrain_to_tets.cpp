// meshprep example: terrain_to_tets
//
// Scattered elevation points become a solid block of tetrahedra that a solver can read. It shows
// the library chain for a terrain: reconstruct_surface (the RBF partition of unity on a grid),
// simplify (bending-energy edge collapse), enhance (against the reconstruction, so the shapes
// improve without leaving the terrain), extrude_to_block (vertical walls and a flat base),
// tetrahedralize_plc (TetGen), improve_tets (flips, smoothing and new inner vertices against
// TetGen's slivers), write_tet_mesh and analyze_tet_quality.
//
// Sample runs (from the repository root, after building into build/):
//   build/bin/terrain_to_tets
//   build/bin/terrain_to_tets examples/data/jacksboro_10k.xyz terrain.msh 4000
//   build/bin/terrain_to_tets examples/data/jacksboro_10k.xyz terrain.vtu 10000
//
// Usage: terrain_to_tets [POINTS.xyz [OUT.msh|.vtu|.vtk|.mesh|.node|.inp [FACES]]]
//   POINTS  scattered x y z samples (default examples/data/jacksboro_10k.xyz)
//   OUT     the tet mesh, format from the extension (default terrain.msh, Gmsh 4.1)
//   FACES   faces of the simplified terrain surface (default 4000)
// Exit codes: 0 success, 1 the work could not be done (e.g. TetGen failed), 2 bad usage or input.

#include "run_example.h"

#include "meshprep/core/io.h"
#include "meshprep/fem/export.h"
#include "meshprep/fem/extrude.h"
#include "meshprep/fem/improve_tets.h"
#include "meshprep/fem/tet_quality.h"
#include "meshprep/fem/tetrahedralize.h"
#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/preprocess/reconstruct/reconstruct.h"
#include "meshprep/preprocess/simplify/simplify.h"
#include "meshprep/quality/surface_distance.h"

#include <cmath>
#include <iostream>
#include <string>

namespace {

using namespace meshprep;
using namespace meshprep::examples;

// The base of the block lies this fraction of the terrain's bounding-box diagonal below its
// lowest point (a relative depth fits a 30 km terrain and a 30 m one alike).
constexpr double kBaseDepthRelative = 0.05;

int terrain_to_tets(const std::string& points_path, const std::string& output_path, std::size_t target_faces) {
  // 1. Read the scattered samples.
  const PointSet points = read_points(points_path);
  std::cout << "1. read " << points.points.size() << " points from " << points_path << '\n';

  // 2. Reconstruct a surface over their footprint (the library's default 300 x 300 grid). The block
  //    of step 5 needs a terrain with a single boundary loop: the holes in the data are kept,
  //    and listed, instead of left out.
  ReconstructParams reconstruct_params;
  reconstruct_params.fill_holes = true;
  const ReconstructResult reconstruction = reconstruct_surface(points.points, reconstruct_params);
  const TriangleSoup& terrain = reconstruction.mesh;
  std::cout << "2. reconstructed " << terrain.points.size() << " vertices, " << terrain.triangles.size()
            << " faces (" << reconstruction.gap_triangles << " left out outside the footprint, "
            << reconstruction.filled_faces.size() << " kept over holes in the data)\n";

  // 3. Simplify it to the target size.
  TriMesh surface = mesh_from_soup(terrain);
  SimplifyParams simplify_params;
  simplify_params.target_faces = target_faces;
  const SimplifyResult simplified = simplify(surface, simplify_params);
  std::cout << "3. simplified to " << simplified.faces_after << " faces (target " << simplified.target_faces
            << ") in " << simplified.seconds << " s\n";

  // 4. Enhance the triangles, staying on the reconstruction (not on the simplified surface).
  const EnhanceResult enhanced = enhance(surface, &terrain, EnhanceParams());
  std::cout << "4. enhanced in " << enhanced.seconds << " s: quality q = 1/radius ratio, 5th percentile "
            << enhanced.before.q_p05 << " -> " << enhanced.after.q_p05 << ", smallest angle "
            << enhanced.before.min_angle_deg << " -> " << enhanced.after.min_angle_deg << " deg\n";

  // 5. Close the open terrain into a block: walls along its boundary, a flat base below it.
  const TriangleSoup top = soup_from_mesh(surface);
  const double depth = kBaseDepthRelative * bbox_diagonal(top);
  const SurfacePlc block = extrude_to_block(top, depth);
  std::cout << "5. extruded to a block of " << block.facets.size() << " facets, base " << depth
            << " below the lowest point\n";

  // 6. Tetrahedralise the block with TetGen (radius-edge ratio <= 1.414, the default).
  TetMesh tets = tetrahedralize_plc(block, TetParams());
  std::cout << "6. tetrahedralized: " << tets.tets.size() << " tets, " << tets.points.size() << " points\n";

  // 7. Improve the tets (the block's boundary kept exactly): TetGen bounds the radius-edge ratio,
  //    which does not see slivers; the improvement raises the smallest dihedral angle.
  const ImproveResult improved = improve_tets(tets);
  std::cout << "7. improved: smallest dihedral " << improved.min_dihedral_before_deg << " -> "
            << improved.min_dihedral_after_deg << " deg, largest " << improved.max_dihedral_before_deg << " -> "
            << improved.max_dihedral_after_deg << " deg (" << improved.stopped_by << ")\n";

  // 8. Write the tet mesh for a solver.
  write_tet_mesh(tets, output_path);
  std::cout << "8. wrote " << output_path << '\n';

  // 9. Measure the tets.
  const TetQualityReport quality = analyze_tet_quality(tets);
  std::cout << "tet quality: tets " << quality.tetrahedra << ", volume " << quality.volume << ", inverted "
            << quality.inverted_tets << ", min dihedral " << quality.min_dihedral_deg.min
            << " deg, radius-edge max " << quality.radius_edge_ratio.max << '\n';
  return kSuccess;
}

}  // namespace

int main(int argc, char** argv) {
  return run_example(argc, argv, "terrain_to_tets [POINTS.xyz [OUT.msh [FACES]]]", 3, [&] {
    const std::string points = argc > 1 ? argv[1] : "examples/data/jacksboro_10k.xyz";
    const std::string output = argc > 2 ? argv[2] : "terrain.msh";
    const double faces = argc > 3 ? parse_positive(argv[3], "FACES") : 4000;
    return terrain_to_tets(points, output, static_cast<std::size_t>(std::lround(faces)));
  });
}
