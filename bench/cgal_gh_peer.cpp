// The speed peer the simplification goal names: CGAL's Garland-Heckbert edge collapse (plane
// policies, normal-change-bounded placement), the fastest all-valid peer in ../shared/anchors.md.
// Not part of the build: bench_simplify.sh compiles it when libcgal-dev is installed, so that our
// time and CGAL's are taken in the same run, alternating (a shared VM's speed swings by 30 %).
// Times the collapse alone, as the anchors do (no I/O). Usage: cgal_gh_peer IN.off RATIO [OUT.off]
// Prints: seconds faces_after.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_placement.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_ratio_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SMS = CGAL::Surface_mesh_simplification;

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: cgal_gh_peer IN.off RATIO [OUT.off]\n";
    return 2;
  }
  Mesh mesh;
  std::ifstream in(argv[1]);
  if (!(in >> mesh) || mesh.is_empty()) {
    std::cerr << argv[1] << ": not a readable OFF surface\n";
    return 2;
  }
  const double ratio = std::atof(argv[2]);
  const auto start = std::chrono::steady_clock::now();
  using Policies = SMS::GarlandHeckbert_plane_policies<Mesh, Kernel>;
  Policies policies(mesh);
  const SMS::Bounded_normal_change_placement<Policies::Get_placement> placement(policies.get_placement());
  SMS::Count_ratio_stop_predicate<Mesh> stop(ratio);
  SMS::edge_collapse(mesh, stop, CGAL::parameters::get_cost(policies.get_cost()).get_placement(placement));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  mesh.collect_garbage();
  if (argc > 3) {
    std::ofstream out(argv[3]);
    out << mesh;
  }
  std::cout << seconds << " " << mesh.number_of_faces() << "\n";
  return 0;
}
