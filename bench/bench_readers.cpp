// Mesh readers on growing files (issue 16 item 5): megabytes per second of each format at two sizes about a factor
// 4 apart. A reader that is linear in the file size shows the same MB/s at both; the OBJ line counter (counting from
// the start of the file for every line) and the VTU prefix copy (per DataArray) were quadratic. Each file is a
// tet box or its boundary surface, written by hooke and read back. Run:
//   build/release/bench/hooke_bench --benchmark_filter=ReadMesh
#include <benchmark/benchmark.h>

#include <filesystem>
#include <hooke/io/mesh_io.hpp>
#include <hooke/io/vtu.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/mesh/topology.hpp>
#include <string>

namespace {

using namespace hooke;
namespace fs = std::filesystem;

const char* kFormats[] = {".msh", ".vtu", ".ele", ".obj", ".off", ".stl"};

// A file of the format at state.range(0) with a box of n^3 cubes (n = state.range(1)): volumes for MSH, VTU and
// TetGen, the boundary surface for OBJ, OFF and STL. Written once per (format, n).
fs::path mesh_file(int format, int n) {
  const std::string ext = kFormats[format];
  const fs::path path = fs::temp_directory_path() / ("hooke_bench_read_" + std::to_string(n) + ext);
  if (fs::exists(path)) return path;
  const mesh::Mesh box = mesh::tet_box(1.0, 1.0, 1.0, n, n, n);
  if (ext == ".msh" || ext == ".vtu" || ext == ".ele") {
    io::write_mesh(path, box);
  } else {
    mesh::Mesh surface = mesh::make_mesh(mesh::ElementKind::kSurfaceTriangle, box.nodes, mesh::boundary_facets(box));
    io::write_mesh(path, surface);
  }
  return path;
}

void BM_ReadMesh(benchmark::State& state) {
  const fs::path path = mesh_file(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  double bytes = static_cast<double>(fs::file_size(path));
  if (path.extension() == ".ele")
    bytes += static_cast<double>(fs::file_size(fs::path(path).replace_extension(".node")));
  io::ReadOptions options;
  options.validate = false;  // the reader alone
  for (auto _ : state) benchmark::DoNotOptimize(io::read_mesh(path, options));
  state.SetLabel(std::string(kFormats[state.range(0)]) + ", " + std::to_string(static_cast<int>(bytes / 1e3)) + " kB");
  state.counters["MB_per_s"] = benchmark::Counter(bytes / 1e6, benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

// Volumes (MSH, VTU, TetGen) at n = 24 and 38, surfaces (OBJ, OFF, STL) at n = 24 and 48: about a factor 4 in
// bytes between the two sizes of each format.
BENCHMARK(BM_ReadMesh)
    ->ArgsProduct({{0, 1, 2}, {24, 38}})
    ->ArgsProduct({{3, 4, 5}, {24, 48}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.5);
