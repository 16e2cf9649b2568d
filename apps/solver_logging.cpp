#include "solver_logging.h"

#include <glog/logging.h>

namespace meshprep::cli {

void quiet_solver_logging(const char* program) {
  FLAGS_logtostderr = true;
  FLAGS_minloglevel = google::GLOG_FATAL;
  google::InitGoogleLogging(program);
}

}  // namespace meshprep::cli
