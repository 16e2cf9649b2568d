#include "meshprep/core/parameter.h"

#include "meshprep/core/errors.h"

#include <cmath>
#include <sstream>

namespace meshprep {

bool Range::contains(double value) const {
  const bool above = lo_open ? value > lo : value >= lo;
  const bool below = hi_open ? value < hi : value <= hi;
  return above && below;
}

std::string Range::text() const {
  return std::string(lo_open ? "(" : "[") + parameter_text(lo) + ", " + parameter_text(hi) +
         (hi_open ? ")" : "]");
}

std::string parameter_text(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::ostringstream out;
  // Whole numbers in full (a count's 100000000 is not 1e+08); others at 6 significant digits.
  if (value == std::floor(value) && std::abs(value) < 1e15) out << static_cast<long long>(value);
  else out << value;
  return out.str();
}

void check_parameter(const char* stage, const ParameterInfo& info, double value) {
  if (!info.range.contains(value))
    throw InvalidInput(std::string(stage) + ": " + info.key + " must be in " + info.range.text() + ", not " +
                       parameter_text(value));
}

}  // namespace meshprep
