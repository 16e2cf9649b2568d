// meshprep example: simplify_and_enhance
//
// A scanned surface is reduced to a fraction of its faces and its triangles are then improved
// without leaving the original: simplify (bending-energy edge collapse) followed by enhance with
// the original scan as the reference. The quality before and after comes from analyze_quality, the
// "after" one measured against the original (Hausdorff distance, volume change).
//
// Sample runs (from the repository root, after building into build/):
//   build/bin/simplify_and_enhance
//   build/bin/simplify_and_enhance examples/data/femur.off femur_30.off 0.3
//   build/bin/simplify_and_enhance examples/data/femur.off femur_10.ply 0.1
//
// Usage: simplify_and_enhance [MESH [OUT [RATIO]]]
//   MESH   a manifold surface, .off .obj .ply .stl (default examples/data/femur.off)
//   OUT    the simplified and enhanced surface (default simplified.off)
//   RATIO  fraction of the faces kept, in (0, 1] (default 0.3)
// Exit codes: 0 success, 1 the work could not be done, 2 bad usage or unreadable/non-manifold input.

#include "run_example.h"

#include "meshprep/core/io.h"
#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/preprocess/simplify/simplify.h"
#include "meshprep/quality/report.h"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <string>

namespace {

using namespace meshprep;
using namespace meshprep::examples;

void print_quality(const std::string& label, const QualityReport& report) {
  std::cout << std::setw(8) << label << ": faces " << report.faces << ", min angle < 20 deg "
            << 100 * report.faces_min_angle_below_20 << " %, smallest angle " << report.min_angle_deg.min
            << " deg, radius ratio p95 " << report.radius_ratio.p95;
  if (report.reference)
    std::cout << ", Hausdorff " << report.reference->hausdorff_relative << " of the diagonal, volume change "
              << report.reference->volume_change_percent.value_or(0) << " %";
  std::cout << '\n';
}

int simplify_and_enhance(const std::string& input_path, const std::string& output_path, double ratio) {
  if (!(ratio <= 1)) throw InvalidInput("RATIO must be in (0, 1], not " + std::to_string(ratio));

  // 1. Read the scan; simplification needs every face in the halfedge mesh (a manifold surface).
  LoadedMesh scan = load_mesh(input_path);
  require_all_faces(scan, "simplification");
  const TriangleSoup& original = scan.soup;

  // 2. Measure it.
  print_quality("before", analyze_quality(original));

  // 3. Simplify: keep `ratio` of the faces.
  SimplifyParams simplify_params;
  simplify_params.keep_ratio = ratio;
  const SimplifyResult simplified = simplify(scan.mesh, simplify_params);
  std::cout << "simplified " << simplified.faces_before << " -> " << simplified.faces_after << " faces (target "
            << simplified.target_faces << ") in " << simplified.seconds << " s\n";

  // 4. Enhance against the original scan. Its collapses may remove faces only within the 1 %
  //    slack that simplify's target leaves, so the result still meets the target.
  EnhanceParams enhance_params;
  const double lowest_allowed = 0.99 * static_cast<double>(simplified.target_faces);
  const double faces = static_cast<double>(simplified.faces_after);
  enhance_params.max_face_change = std::max(0.0, (faces - lowest_allowed) / faces);
  const EnhanceResult enhanced = enhance(scan.mesh, &original, enhance_params);
  std::cout << "enhanced in " << enhanced.seconds << " s (" << enhanced.kept_round << " rounds kept, "
            << enhanced.flips << " flips)\n";

  // 5. Write the result and measure it against the original.
  const TriangleSoup output = soup_from_mesh(scan.mesh);
  write_soup(output, output_path);
  print_quality("after", analyze_quality(output, QualityParams(), &original));
  std::cout << "wrote " << output_path << '\n';
  return kSuccess;
}

}  // namespace

int main(int argc, char** argv) {
  return run_example(argc, argv, "simplify_and_enhance [MESH [OUT [RATIO]]]", 3, [&] {
    const std::string input = argc > 1 ? argv[1] : "examples/data/femur.off";
    const std::string output = argc > 2 ? argv[2] : "simplified.off";
    const double ratio = argc > 3 ? parse_positive(argv[3], "RATIO") : 0.3;
    return simplify_and_enhance(input, output, ratio);
  });
}
