// libFuzzer target: the OBJ reader on arbitrary bytes (scripts/fuzz.sh runs it).
#include "soup_fuzzer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return meshprep::fuzz::fuzz_soup_reader("input.obj", data, size);
}
