#pragma once
/// \file repair_solid.h
/// The repair (repair.h) as the commands and the pipeline run it: where its envelope route rebuilt
/// the solid on a grid, the grid's surface (several faces per cell it crosses, many of them tiny)
/// is simplified (simplify.h) back towards the input's face count.

#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/repair/repair.h"

namespace meshprep {

/// repair(surface, params) with the fidelity bound, unless given, set to the enhancement's
/// (EnhanceParams::kLargestAutoDeviation: the envelope lists the places farther than it); if the
/// envelope route ran, its surface is then simplified with simplify.h's guards (topology, no
/// crossing made, no angle under its floor made) towards the input's face count, each collapse's
/// estimated deviation under a quarter of that bound. RepairEnvelope::reduced_faces says to what.
RepairResult repair_solid(TriangleSoup& surface, RepairParams params);

}  // namespace meshprep
