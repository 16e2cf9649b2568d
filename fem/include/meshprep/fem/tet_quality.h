#pragma once
/// \file tet_quality.h
/// Quality of a tetrahedral mesh: dihedral angles, radius-edge ratio (circumradius over the
/// shortest edge; sqrt(6)/4 = 0.612 for the regular tet, TetGen's -q bound is on this ratio),
/// volumes, tets per region.

#include "meshprep/fem/tet_mesh.h"
#include "meshprep/quality/statistics.h"

#include <map>
#include <nlohmann/json.hpp>

namespace meshprep {

/// Shape of one tetrahedron.
struct TetShape {
  double volume = 0;            ///< signed
  double min_dihedral_deg = 0;  ///< smallest of the six dihedral angles
  double max_dihedral_deg = 0;
  double radius_edge_ratio = 0;  ///< circumradius / shortest edge (+inf for a flat tet)
};

/// Dihedral angles come from the faces' normals (interior angle = pi - angle between the outward
/// normals), so they are those of the geometric tet whatever its orientation; a flat tet has
/// angles of 0 and/or 180 degrees.
TetShape tet_shape(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3);

struct TetQualityReport {
  std::size_t points = 0;
  std::size_t tetrahedra = 0;
  double volume = 0;  ///< sum of the tets' signed volumes
  std::size_t inverted_tets = 0;  ///< volume <= 0
  Distribution min_dihedral_deg{}, max_dihedral_deg{}, radius_edge_ratio{};
  double tets_min_dihedral_below_10 = 0;  ///< fraction
  std::map<int, std::size_t> tets_per_region;
  std::vector<double> min_dihedral_per_tet;     ///< for histograms
  std::vector<double> radius_edge_per_tet;      ///< for histograms
};

/// Distributions ignore non-finite values (the radius-edge ratio of flat tets).
/// \throws InvalidInput if tet_regions' size differs from tets' or a tet references a missing point.
TetQualityReport analyze_tet_quality(const TetMesh& mesh);

/// JSON keys: points, tetrahedra, volume, inverted_tets, min_dihedral_deg {min,mean,p5,p50,p95,max},
/// max_dihedral_deg {...}, radius_edge_ratio {...}, tets_min_dihedral_below_10, tets_per_region {"1": n}.
nlohmann::ordered_json to_json(const TetQualityReport& report);

}  // namespace meshprep
