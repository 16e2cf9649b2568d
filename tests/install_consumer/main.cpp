// Uses the installed meshprep headers and libraries: reads a mesh and prints its face count,
// whether it is closed, and its radius ratio p95 (analyze_quality runs the self-intersection test
// on exact predicates backed by GMP, so the link needs the package's dependencies too).
// Usage: install_consumer MESH; exit 2 if the mesh cannot be read.
#include <meshprep/core/errors.h>
#include <meshprep/core/io.h>
#include <meshprep/quality/report.h>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: install_consumer MESH\n";
    return 2;
  }
  try {
    const meshprep::QualityReport report = meshprep::analyze_quality(meshprep::read_soup(argv[1]));
    std::cout << "faces " << report.faces << " closed " << report.closed << " radius_ratio_p95 "
              << report.radius_ratio.p95 << '\n';
    return 0;
  } catch (const meshprep::Error& e) {
    std::cerr << "install_consumer: " << e.what() << '\n';
    return 2;
  }
}
