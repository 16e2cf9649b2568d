// libFuzzer target: the Medit .mesh reader on arbitrary bytes (scripts/fuzz.sh runs it).
#include "tet_mesh_fuzzer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return meshprep::fuzz::fuzz_tet_mesh_reader(meshprep::detail::TetFormat::Medit, "input.mesh", data, size);
}
