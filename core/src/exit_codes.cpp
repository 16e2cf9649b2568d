#include "meshprep/core/exit_codes.h"

#include "meshprep/core/errors.h"

namespace meshprep {

ExitCode exit_code_of(const std::exception& failure) {
  if (dynamic_cast<const TimeLimitReached*>(&failure)) return ExitCode::time_limit;
  if (dynamic_cast<const Cancelled*>(&failure)) return ExitCode::interrupted;
  if (dynamic_cast<const WriteError*>(&failure)) return ExitCode::failed;
  if (dynamic_cast<const InvalidInput*>(&failure) || dynamic_cast<const IoError*>(&failure)) return ExitCode::bad_input;
  return ExitCode::failed;
}

}  // namespace meshprep
