// libFuzzer target: the legacy .vtk reader (ASCII and BINARY) on arbitrary bytes (scripts/fuzz.sh runs it).
#include "tet_mesh_fuzzer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return meshprep::fuzz::fuzz_tet_mesh_reader(meshprep::detail::TetFormat::VtkLegacy, "input.vtk", data, size);
}
