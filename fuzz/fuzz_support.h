#pragma once
/// \file fuzz_support.h
/// What every fuzz target checks. The library may refuse an input only with its documented errors
/// (InvalidInput, IoError); any other exception escapes to libFuzzer, which reports it as a crash,
/// like a sanitizer finding, a leak or a timeout. What an input yields when it is accepted must
/// keep the library's promises: a broken invariant aborts with a message.

#include "meshprep/core/errors.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace meshprep::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Aborts, naming the broken invariant, unless `holds`.
inline void require(bool holds, const char* invariant) {
  if (holds) return;
  std::fprintf(stderr, "fuzz invariant broken: %s\n", invariant);
  std::abort();
}

/// Runs `parse`; the library's documented errors mean a refused input, anything else escapes.
template <class Parse>
void refuse_only_with_meshprep_errors(Parse parse) {
  try {
    parse();
  } catch (const InvalidInput&) {
  } catch (const IoError&) {
  }
}

}  // namespace meshprep::fuzz
