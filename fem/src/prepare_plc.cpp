#include "meshprep/fem/prepare_plc.h"

#include "meshprep/core/errors.h"
#include "meshprep/fem/extrude.h"

#include <utility>

namespace meshprep {

PreparedPlc prepare_plc(const TriangleSoup& surface, std::optional<double> extrude_depth) {
  PreparedPlc prepared;
  if (extrude_depth) {
    try {
      prepared.plc = extrude_to_block(surface, *extrude_depth);
    } catch (const InvalidInput& e) {
      prepared.extrusion_problem = e.what();
    }
    return prepared;
  }
  prepared.readiness = check_fem_readiness(surface);
  if (!prepared.readiness->ready()) return prepared;
  if (!prepared.readiness->inward_oriented) {
    prepared.plc = plc_from_surface(surface, 1);
    return prepared;
  }
  TriangleSoup flipped = surface;
  for (Triangle& t : flipped.triangles) std::swap(t[1], t[2]);
  prepared.flipped_inward = true;
  prepared.plc = plc_from_surface(flipped, 1);
  return prepared;
}

}  // namespace meshprep
