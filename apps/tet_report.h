#pragma once
// The report of `meshprep quality` on a tetrahedral mesh: what the file held beyond the mesh, the
// tets' quality (analyze_tet_quality, as its to_json gives it) and the topology of the boundary
// (the faces of one tet), as JSON, and a plain-text summary printed from that JSON, so that every
// figure the quality module adds shows in both.

#include "meshprep/fem/import.h"

#include <nlohmann/json.hpp>

#include <ostream>

namespace meshprep::cli {

/// Notes on stderr about what the reader changed or skipped (reoriented tets, skipped elements,
/// duplicate triangles), so that nothing is lost quietly.
void note_read_changes(const TetReadReport& read);

/// The report as aligned plain text: the counts, every distribution of "tet_quality" as a table
/// row, then the boundary.
void write_tet_summary(std::ostream& out, const nlohmann::ordered_json& report);

}  // namespace meshprep::cli
