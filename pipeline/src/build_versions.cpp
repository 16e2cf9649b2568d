#include "meshprep/pipeline/pipeline_outputs.h"

#include "meshprep/core/mesh.h"

#include <ceres/version.h>
#include <oneapi/tbb/version.h>
#include <png.h>

#include <string>

namespace meshprep {

nlohmann::ordered_json build_versions() {
  auto dotted = [](int a, int b, int c) { return std::to_string(a) + "." + std::to_string(b) + "." + std::to_string(c); };
  return {{"meshprep", MESHPREP_VERSION},
          {"eigen", dotted(EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
          {"openmesh", dotted(OM_GET_VER, OM_GET_MAJ, OM_GET_MIN)},
          {"ceres", CERES_VERSION_STRING},
          {"tbb", TBB_VERSION_STRING},
          {"tetgen", "1.5"},  // Debian's libtet1.5 (tetgen.h has no version macro)
          {"nlohmann_json", dotted(NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH)},
          {"libpng", PNG_LIBPNG_VER_STRING},
          {"compiler", __VERSION__}};
}

}  // namespace meshprep
