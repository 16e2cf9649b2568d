#include "meshprep/quality/quality_parameters.h"

namespace meshprep {

const QualityParameters& quality_parameters() {
  static const QualityParameters parameters{
      {"distance_samples", "--samples",
       "area-weighted random samples per direction for the Hausdorff and RMS distances to the reference",
       {1000, 100000000}}};
  return parameters;
}

}  // namespace meshprep
