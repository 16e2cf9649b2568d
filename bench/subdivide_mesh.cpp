// subdivide_mesh IN OUT LEVELS: Loop subdivision (1 face -> 4 per level, OpenMesh's LoopT), to make
// the large smooth inputs of the scale benchmarks (bunny00 at 2 levels: 1.2 M faces).
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"

#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <cstdlib>
#include <iostream>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: subdivide_mesh IN OUT LEVELS\n";
    return 2;
  }
  try {
    meshprep::LoadedMesh loaded = meshprep::load_mesh(argv[1]);
    OpenMesh::Subdivider::Uniform::LoopT<meshprep::TriMesh, double> loop;
    loop.attach(loaded.mesh);
    loop(static_cast<std::size_t>(std::atoi(argv[3])));
    loop.detach();
    meshprep::write_soup(meshprep::soup_from_mesh(loaded.mesh), argv[2]);
  } catch (const meshprep::Error& e) {
    std::cerr << "subdivide_mesh: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
