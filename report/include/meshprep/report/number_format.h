#pragma once
/// \file number_format.h
/// Locale-independent number formatting shared by the report writers.

#include <charconv>
#include <cmath>
#include <string>

namespace meshprep {

/// `v` with `significant` significant digits, like printf's %.<significant>g but independent of
/// the C locale; non-finite values are written "inf", "-inf" and "nan".
inline std::string format_number(double v, int significant) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, significant);
  return {buffer, result.ptr};
}

/// `v` in scientific notation with `decimals` digits after the point (1.24e-03 for 2).
inline std::string format_scientific(double v, int decimals) {
  if (!std::isfinite(v)) return format_number(v, 1);
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::scientific, decimals);
  return {buffer, result.ptr};
}

/// `v` with `decimals` digits after the point (like %.<decimals>f).
inline std::string format_fixed(double v, int decimals) {
  if (!std::isfinite(v)) return format_number(v, 1);
  char buffer[400];  // DBL_MAX has 309 digits before the point
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, decimals);
  return {buffer, result.ptr};
}

}  // namespace meshprep
