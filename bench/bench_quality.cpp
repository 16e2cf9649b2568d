// Quality-report timings on bunny00, side by side with OpenMesh's own OFF reader as the peer
// for reading, and the self-intersection search on fans (tests/test_meshes.h). Run:
// build/bin/bench_quality (needs ../shared/data beside the clone).
#include "meshprep/core/io.h"
#include "meshprep/quality/report.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/surface_distance.h"
#include "meshprep/quality/topology.h"
#include "meshprep/quality/triangle_bvh.h"

#include "test_meshes.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <benchmark/benchmark.h>

#include <filesystem>

namespace {

const std::string kBunny = std::string(MESHPREP_SHARED_DATA_DIR) + "/meshes/bunny00.off";

bool have_data(benchmark::State& state) {
  if (std::filesystem::exists(kBunny)) return true;
  state.SkipWithError("../shared/data/meshes/bunny00.off not found");
  return false;
}

void read_meshprep(benchmark::State& state) {
  if (!have_data(state)) return;
  for (auto _ : state) benchmark::DoNotOptimize(meshprep::read_soup(kBunny));
}
BENCHMARK(read_meshprep)->Unit(benchmark::kMillisecond);

void read_openmesh_peer(benchmark::State& state) {
  if (!have_data(state)) return;
  for (auto _ : state) {
    meshprep::TriMesh mesh;
    benchmark::DoNotOptimize(OpenMesh::IO::read_mesh(mesh, kBunny));
  }
}
BENCHMARK(read_openmesh_peer)->Unit(benchmark::kMillisecond);

void topology(benchmark::State& state) {
  if (!have_data(state)) return;
  const auto soup = meshprep::read_soup(kBunny);
  for (auto _ : state) benchmark::DoNotOptimize(meshprep::analyze_topology(soup));
}
BENCHMARK(topology)->Unit(benchmark::kMillisecond);

void bvh_build(benchmark::State& state) {
  if (!have_data(state)) return;
  const auto soup = meshprep::read_soup(kBunny);
  for (auto _ : state) benchmark::DoNotOptimize(meshprep::TriangleBvh(soup));
}
BENCHMARK(bvh_build)->Unit(benchmark::kMillisecond);

void self_intersections(benchmark::State& state) {
  if (!have_data(state)) return;
  const auto soup = meshprep::read_soup(kBunny);
  for (auto _ : state) benchmark::DoNotOptimize(meshprep::find_self_intersections(soup));
}
BENCHMARK(self_intersections)->Unit(benchmark::kMillisecond);

// Issue 30: one vertex's fan of long thin faces, alone or as the caps of a cylinder (argument:
// the polygon's corners). The counter is the number of pairs given to the exact test.
void search_and_count(benchmark::State& state, const meshprep::TriangleSoup& soup) {
  for (auto _ : state) {
    const meshprep::SelfIntersections found = meshprep::find_self_intersections(soup);
    state.counters["pairs"] = static_cast<double>(found.count);
    state.counters["exact_tests"] = static_cast<double>(found.exact_tests);
  }
}

void self_intersections_fan(benchmark::State& state) {
  search_and_count(state, meshprep::test::fan_triangulated_polygon(static_cast<int>(state.range(0))));
}
BENCHMARK(self_intersections_fan)->Arg(2000)->Arg(5000)->Arg(20000)->Unit(benchmark::kMillisecond);

void self_intersections_fan_capped_cylinder(benchmark::State& state) {
  search_and_count(state, meshprep::test::cylinder_with_fan_caps(static_cast<int>(state.range(0))));
}
BENCHMARK(self_intersections_fan_capped_cylinder)->Arg(2000)->Arg(6000)->Unit(benchmark::kMillisecond);

void full_report(benchmark::State& state) {
  if (!have_data(state)) return;
  const auto soup = meshprep::read_soup(kBunny);
  for (auto _ : state) benchmark::DoNotOptimize(meshprep::analyze_quality(soup));
}
BENCHMARK(full_report)->Unit(benchmark::kMillisecond);

void report_with_reference(benchmark::State& state) {
  if (!have_data(state)) return;
  const auto soup = meshprep::read_soup(kBunny);
  for (auto _ : state) benchmark::DoNotOptimize(meshprep::analyze_quality(soup, {}, &soup));
}
BENCHMARK(report_with_reference)->Unit(benchmark::kMillisecond);

// The symmetric distance between bunny00 and its 10 % decimation (1,000,000 samples a direction):
// the closest-point queries every fidelity figure of the pipeline is made of.
void surface_distance_to_decimated(benchmark::State& state) {
  const std::string decimated = std::string(MESHPREP_SHARED_DATA_DIR) + "/meshes/decimated/bunny00_0.1_openmesh.off";
  if (!have_data(state)) return;
  const auto soup = meshprep::read_soup(kBunny);
  const auto coarse = meshprep::read_soup(decimated);
  for (auto _ : state) benchmark::DoNotOptimize(meshprep::surface_distance(soup, coarse));
}
BENCHMARK(surface_distance_to_decimated)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
