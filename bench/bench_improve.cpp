// bench_improve SURFACE... : for each closed surface, TetGen (-pq1.414, with -Y unless --split)
// and then the tet improvement on its tets, timed side by side in one process, one thread:
// prints one line per surface with TetGen's and the improvement's time and the dihedral angles
// before and after. The surfaces are typically `meshprep pipeline`'s surface.ply outputs.
#include "meshprep/core/io.h"
#include "meshprep/fem/improve_tets.h"
#include "meshprep/fem/tet_quality.h"
#include "meshprep/fem/tetrahedralize.h"

#include <tbb/global_control.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

using namespace meshprep;

int main(int argc, char** argv) {
  bool split = false;
  ImproveParams params;
  std::vector<std::string> inputs;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--split") == 0) split = true;
    else if (std::strcmp(argv[i], "--goal") == 0 && i + 2 < argc) {
      params.goal_min_dihedral_deg = std::atof(argv[++i]);
      params.goal_max_dihedral_deg = std::atof(argv[++i]);
    } else inputs.push_back(argv[i]);
  }
  if (inputs.empty()) {
    std::fprintf(stderr, "usage: bench_improve [--split] [--goal MIN MAX] SURFACE...\n");
    return 2;
  }
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  std::printf("%-28s %8s %8s %8s %7s | %7s %7s %6s | %7s %7s %6s | %5s %5s %5s %5s %s\n", "surface", "tets", "tetgen_s",
              "improv_s", "ratio", "min_b", "max_b", "bad_b", "min_a", "max_a", "bad_a", "edge", "face", "move",
              "ins", "stop (compound)");
  for (const std::string& path : inputs) {
    const TriangleSoup surface = read_soup(path);
    TetParams tet_params;
    tet_params.keep_surface = !split;
    const auto t0 = std::chrono::steady_clock::now();
    TetMesh tets;
    try {
      tets = tetrahedralize_plc(plc_from_surface(surface), tet_params);
    } catch (const TetgenError& e) {
      std::printf("%-28s TetGen: %s\n", path.c_str(), e.what());
      continue;
    }
    const double tetgen = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double volume_before = analyze_tet_quality(tets).volume;
    const ImproveResult r = improve_tets(tets, params);
    const TetQualityReport after = analyze_tet_quality(tets);
    // The pipeline's outputs are all surface.ply: name those by their folder.
    const std::filesystem::path file(path);
    std::string name = file.stem().string();
    if (name == "surface" && !file.parent_path().filename().empty()) name = file.parent_path().filename().string();
    std::printf("%-28s %8zu %8.3f %8.3f %7.2f | %7.2f %7.2f %6zu | %7.2f %7.2f %6zu | %5zu %5zu %5zu %5zu %s (cmp %zu, ctr %zu, dV %.1e, inv %zu, limiting %zu, bound %.2f)\n",
                name.c_str(), r.tets_after, tetgen, r.seconds, r.seconds / tetgen, r.min_dihedral_before_deg,
                r.max_dihedral_before_deg, r.below_goal_before, r.min_dihedral_after_deg, r.max_dihedral_after_deg,
                r.below_goal_after, r.edge_removals, r.multi_face_removals, r.vertex_moves, r.inserted_vertices,
                r.stopped_by.c_str(), r.compound_moves, r.contractions, (after.volume - volume_before) / volume_before, after.inverted_tets,
                r.limiting_edge_count, r.surface_bound_deg);
    std::fflush(stdout);
  }
  return 0;
}
