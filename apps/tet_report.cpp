// tet_mesh_report, note_read_changes, write_tet_summary (tet_report.h).
#include "tet_report.h"

#include "meshprep/report/number_format.h"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace meshprep::cli {
namespace {

using Json = nlohmann::ordered_json;

// "min_dihedral_deg" -> "min dihedral (deg)".
std::string label_of(std::string key) {
  const std::string degrees = "_deg";
  const bool in_degrees = key.size() > degrees.size() && key.compare(key.size() - degrees.size(), degrees.size(), degrees) == 0;
  if (in_degrees) key.resize(key.size() - degrees.size());
  std::replace(key.begin(), key.end(), '_', ' ');
  return in_degrees ? key + " (deg)" : key;
}

bool is_distribution(const Json& value) { return value.is_object() && value.contains("p50"); }

// Fractions of the tets ("tets_min_dihedral_below_10") read best as percentages.
bool is_fraction(const std::string& key) {
  return key.find("_below_") != std::string::npos || key.find("_above_") != std::string::npos;
}

std::string value_text(const std::string& key, const Json& value) {
  if (value.is_null()) return "n/a";
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  if (value.is_number_integer()) return value.dump();
  if (value.is_number()) {
    return is_fraction(key) ? format_fixed(100 * value.get<double>(), 2) + " %" : format_number(value.get<double>(), 4);
  }
  if (value.is_object()) {  // {"1": 12, "2": 4}
    std::string text;
    for (const auto& [k, v] : value.items()) text += (text.empty() ? "" : ", ") + k + ": " + value_text(k, v);
    return text;
  }
  return value.dump();
}

using Rows = std::vector<std::pair<std::string, std::string>>;

void write_rows(std::ostream& out, const Rows& rows, std::size_t width) {
  for (const auto& [label, text] : rows) out << "  " << std::left << std::setw(int(width + 2)) << label << text << '\n';
}

void write_distributions(std::ostream& out, const std::vector<std::pair<std::string, const Json*>>& distributions) {
  const char* const columns[] = {"min", "mean", "p5", "p50", "p95", "max"};
  std::size_t label_width = std::string("tet shape").size();
  for (const auto& [label, d] : distributions) label_width = std::max(label_width, label.size() + 2);
  std::vector<std::vector<std::string>> cells;
  std::vector<std::size_t> widths;
  for (const char* column : columns) widths.push_back(std::string(column).size());
  for (const auto& [label, d] : distributions) {
    cells.emplace_back();
    for (std::size_t c = 0; c < std::size(columns); ++c) {
      cells.back().push_back(value_text(columns[c], (*d)[columns[c]]));
      widths[c] = std::max(widths[c], cells.back().back().size());
    }
  }
  out << std::left << std::setw(int(label_width)) << "tet shape" << std::right;
  for (std::size_t c = 0; c < std::size(columns); ++c) out << "  " << std::setw(int(widths[c])) << columns[c];
  out << '\n';
  for (std::size_t r = 0; r < distributions.size(); ++r) {
    out << "  " << std::left << std::setw(int(label_width - 2)) << distributions[r].first << std::right;
    for (std::size_t c = 0; c < cells[r].size(); ++c) out << "  " << std::setw(int(widths[c])) << cells[r][c];
    out << '\n';
  }
  out << std::left;
}

// The worst tets (tet_quality's worst_tets), one line each: where to look in a viewer.
void write_worst_tets(std::ostream& out, const Json& worst) {
  if (worst.empty()) return;
  out << "Worst tets (smallest dihedral first): index, centre, min / max dihedral (deg), radius-edge, scaled Jacobian\n";
  for (const Json& t : worst) {
    const Json& c = t["centre"];
    out << "  " << t["index"].dump() << "  (" << value_text("x", c[0]) << ", " << value_text("y", c[1]) << ", "
        << value_text("z", c[2]) << ")  " << value_text("min", t["min_dihedral_deg"]) << " / "
        << value_text("max", t["max_dihedral_deg"]) << "  " << value_text("r", t["radius_edge_ratio"]) << "  "
        << value_text("j", t["scaled_jacobian"]) << '\n';
  }
}

}  // namespace

void note_read_changes(const TetReadReport& read) {
  const auto note = [&](std::size_t count, const char* what) {
    if (count > 0) std::cerr << "meshprep: note: " << read.path << ": " << count << ' ' << what << '\n';
  };
  note(read.tets_reoriented, "tets of negative volume, every tet of their region, were turned over (a mirrored region)");
  note(read.tets_inverted,
       "tets have negative volume among positive neighbours: left as they are, inverted (the mesh is tangled)");
  note(read.elements_ignored, "points, lines or other lower-dimensional elements were skipped");
  note(read.duplicate_triangles, "triangles listed twice were read once (with the first one's tag)");
  note(read.internal_faces,
       "triangles lie inside a region (each a face of two of its tets): kept with their tags as an internal surface, "
       "and written as tagged triangles like the boundary");
}

void write_tet_summary(std::ostream& out, const Json& report) {
  Rows counts, boundary;
  std::vector<std::pair<std::string, const Json*>> distributions;
  for (const auto& [key, value] : report["tet_quality"].items()) {
    if (value.is_array()) continue;  // the worst tets: a table of their own
    if (is_distribution(value))
      distributions.emplace_back(label_of(key), &value);
    else
      counts.emplace_back(label_of(key), value_text(key, value));
  }
  for (const auto& [key, value] : report["boundary"].items()) boundary.emplace_back(label_of(key), value_text(key, value));
  std::size_t width = 0;
  for (const Rows* rows : {&counts, &boundary})
    for (const auto& row : *rows) width = std::max(width, row.first.size());

  out << "Tet mesh quality: " << report["file"].get<std::string>() << " ("
      << report["input"]["format"].get<std::string>() << ")\n";
  write_rows(out, counts, width);
  write_distributions(out, distributions);
  if (report["tet_quality"].contains("worst_tets")) write_worst_tets(out, report["tet_quality"]["worst_tets"]);
  out << "Boundary (the faces of one tet)\n";
  write_rows(out, boundary, width);
}

}  // namespace meshprep::cli
