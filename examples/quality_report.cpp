// meshprep example: quality_report
//
// The quality report of a surface mesh, in the three forms the library writes: the text summary
// (write_text_summary), JSON (to_json; the keys are the QualityReport fields) and one
// self-contained HTML page with histograms (write_html). analyze_quality measures topology
// (closed, manifold, genus, self-intersections), geometry and the shape of every triangle.
//
// Sample runs (from the repository root, after building into build/):
//   build/bin/quality_report
//   build/bin/quality_report examples/data/femur.off femur_quality
//   build/bin/quality_report ../shared/data/meshes/bunny00.off bunny
//
// Usage: quality_report [MESH [PREFIX]]
//   MESH    a surface mesh, .off .obj .ply .stl (default examples/data/femur.off)
//   PREFIX  writes PREFIX.json and PREFIX.html (default quality)
// Exit codes: 0 success, 2 bad usage or unreadable input.

#include "run_example.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/core/io.h"
#include "meshprep/quality/report.h"
#include "meshprep/report/report_writers.h"

#include <iostream>
#include <string>

namespace {

using namespace meshprep;
using namespace meshprep::examples;

int quality_report(const std::string& mesh_path, const std::string& prefix) {
  // 1. Read the faces exactly as the file holds them (no repair), so the report sees the file.
  const TriangleSoup soup = read_soup(mesh_path);

  // 2. Measure.
  QualityReport report = analyze_quality(soup);
  report.path = mesh_path;

  // 3. The text summary.
  write_text_summary(std::cout, report);

  // 4. JSON, written atomically (a failed write leaves no half file).
  const std::string json_path = prefix + ".json";
  write_file_atomically(json_path, [&](std::ostream& out) { out << to_json(report).dump(2) << '\n'; });

  // 5. The HTML page, with pictures of the surface coloured by radius ratio.
  const std::string html_path = prefix + ".html";
  write_html(html_path, soup, report);
  std::cout << "wrote " << json_path << " and " << html_path << '\n';
  return kSuccess;
}

}  // namespace

int main(int argc, char** argv) {
  return run_example(argc, argv, "quality_report [MESH [PREFIX]]", 2, [&] {
    const std::string mesh = argc > 1 ? argv[1] : "examples/data/femur.off";
    const std::string prefix = argc > 2 ? argv[2] : "quality";
    return quality_report(mesh, prefix);
  });
}
