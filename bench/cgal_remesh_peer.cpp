// The remeshing peer issue 32 names: CGAL's isotropic remeshing
// (CGAL::Polygon_mesh_processing::isotropic_remeshing), beside `meshprep enhance` in
// bench/bench_corpus.sh. Not part of the build: the bench compiles it when libcgal-dev is installed.
// Target edge length = the input's mean edge length, or, given FACES, the equilateral edge that
// tiles the input's area with that many faces (to time CGAL at meshprep enhance's face count, as
// issue 32's time goal asks), 3 iterations. Sharp edges (dihedral angle
// > 45 degrees, PMP::detect_sharp_edges) and border edges are constrained: they may be split or
// collapsed along their polyline but are never flipped and their vertices only stay on them; the
// corners of the feature graph (vertices with 1 or >= 3 sharp edges) do not move at all. (CGAL's
// protect_constraints(true), which forbids splitting them, is not used: it does not terminate
// reliably when constrained edges are much longer than the target, as CAD edges are.)
// Times the remeshing alone (no I/O), one thread (the function is sequential).
// Usage: cgal_remesh_peer IN.off OUT.off [FACES]   Prints: seconds faces_after target_edge_length
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: cgal_remesh_peer IN.off OUT.off [FACES]\n";
    return 2;
  }
  Mesh mesh;
  std::ifstream in(argv[1]);
  if (!(in >> mesh) || mesh.is_empty() || !CGAL::is_triangle_mesh(mesh) || !mesh.is_valid(false)) {
    std::cerr << argv[1] << ": not a readable OFF triangle surface\n";
    return 2;
  }
  double total = 0;
  for (auto e : mesh.edges()) total += PMP::edge_length(e, mesh);
  double target = total / static_cast<double>(mesh.number_of_edges());
  if (argc > 3) {
    const double faces = std::atof(argv[3]);
    if (!(faces > 0)) {
      std::cerr << argv[3] << ": FACES must be a positive number\n";
      return 2;
    }
    target = std::sqrt(PMP::area(mesh) / (faces * std::sqrt(3.0) / 4.0));
  }

  const auto start = std::chrono::steady_clock::now();
  auto sharp = mesh.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
  PMP::detect_sharp_edges(mesh, 45.0, sharp);
  auto corner = mesh.add_property_map<Mesh::Vertex_index, bool>("v:corner", false).first;
  for (auto v : mesh.vertices()) {
    int n = 0;
    for (auto h : CGAL::halfedges_around_target(v, mesh))
      if (sharp[mesh.edge(h)] || mesh.is_border(mesh.edge(h))) ++n;
    corner[v] = n == 1 || n >= 3;
  }
  PMP::isotropic_remeshing(faces(mesh), target, mesh,
                           CGAL::parameters::number_of_iterations(3)
                               .edge_is_constrained_map(sharp)
                               .vertex_is_constrained_map(corner)
                               .protect_constraints(false));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  mesh.remove_property_map(sharp);
  mesh.remove_property_map(corner);
  mesh.collect_garbage();
  std::ofstream out(argv[2]);
  out.precision(17);
  out << mesh;
  std::cout << seconds << " " << mesh.number_of_faces() << " " << target << "\n";
  return out ? 0 : 1;
}
