// libFuzzer target: the .vtu reader (VTK XML, every data layout) on arbitrary bytes (scripts/fuzz.sh runs it).
#include "tet_mesh_fuzzer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return meshprep::fuzz::fuzz_tet_mesh_reader(meshprep::detail::TetFormat::Vtu, "input.vtu", data, size);
}
