// libFuzzer target: the PLY (ASCII and binary, both byte orders) reader on arbitrary bytes (scripts/fuzz.sh runs it).
#include "soup_fuzzer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return meshprep::fuzz::fuzz_soup_reader("input.ply", data, size);
}
