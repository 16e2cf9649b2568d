// libFuzzer target: the .msh reader (Gmsh 4.1 and 2.x, ASCII and binary) on arbitrary bytes (scripts/fuzz.sh runs it).
#include "tet_mesh_fuzzer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return meshprep::fuzz::fuzz_tet_mesh_reader(meshprep::detail::TetFormat::Gmsh, "input.msh", data, size);
}
