// subdivide_mesh IN OUT LEVELS [SQRT3_LEVELS]: Loop subdivision (1 face -> 4 per level, OpenMesh's
// LoopT), then optionally sqrt(3) subdivision (1 face -> 3 per level, Kobbelt 2000, OpenMesh's
// Sqrt3T), to make the large smooth inputs of the scale benchmarks (bunny00 at 2 levels: 1.2 M
// faces; at 2 and 2 sqrt(3) levels: 10.9 M).
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"

#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>

#include <cstdlib>
#include <iostream>

int main(int argc, char** argv) {
  if (argc != 4 && argc != 5) {
    std::cerr << "usage: subdivide_mesh IN OUT LEVELS [SQRT3_LEVELS]\n";
    return 2;
  }
  try {
    meshprep::LoadedMesh loaded = meshprep::load_mesh(argv[1]);
    OpenMesh::Subdivider::Uniform::LoopT<meshprep::TriMesh, double> loop;
    loop.attach(loaded.mesh);
    loop(static_cast<std::size_t>(std::atoi(argv[3])));
    loop.detach();
    if (argc == 5) {
      OpenMesh::Subdivider::Uniform::Sqrt3T<meshprep::TriMesh, double> sqrt3;
      sqrt3.attach(loaded.mesh);
      sqrt3(static_cast<std::size_t>(std::atoi(argv[4])));
      sqrt3.detach();
    }
    meshprep::write_soup(meshprep::soup_from_mesh(loaded.mesh), argv[2]);
  } catch (const meshprep::Error& e) {
    std::cerr << "subdivide_mesh: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
