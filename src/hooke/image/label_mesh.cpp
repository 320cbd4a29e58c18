// Label image -> surface (ITK) -> cleaned surface -> tets (Netgen) -> a label per tet. docs/images.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/image/detail/itk_bridge.hpp>
#include <hooke/image/label_mesh.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/io/mesher.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/surface_cleanup.hpp>
#include <hooke/mesh/tet_quality.hpp>
#include <map>
#include <set>

namespace hooke::image {
namespace {

// The fraction of each block of f[0] x f[1] x f[2] voxels in the selected labels, with one empty block around the
// image (so that the surface closes where the body meets the image's edge), on a grid in m.
detail::Grid block_fractions(const LabelImage& image, const std::set<int>& selected, const std::array<int, 3>& f,
                             std::vector<float>& values) {
  detail::Grid g;
  // Block (I, J, K) (1-based inside the padding) covers the voxels f (I - 1) .. f I - 1, whose centre is at fine
  // index f I - (f + 1) / 2: block (0, 0, 0), the padding, sits at fine index -(f + 1) / 2.
  const Vec3 first(-(f[0] + 1) / 2.0, -(f[1] + 1) / 2.0, -(f[2] + 1) / 2.0);
  const Vec3 origin = image.origin + image.direction * image.spacing.cwiseProduct(first);
  for (int a = 0; a < 3; ++a) {
    const auto s = static_cast<std::size_t>(a);
    g.size[s] = (image.size[s] + f[s] - 1) / f[s] + 2;
    g.spacing[s] = image.spacing(a) * f[s];
    g.origin[s] = origin(a);
    for (int b = 0; b < 3; ++b) g.direction[static_cast<std::size_t>(3 * b + a)] = image.direction(b, a);
  }
  values.assign(static_cast<std::size_t>(g.size[0] * g.size[1] * g.size[2]), 0.0f);
  const auto per_block = static_cast<float>(1.0 / (static_cast<double>(f[0]) * f[1] * f[2]));
  for (int k = 0; k < image.size[2]; ++k)
    for (int j = 0; j < image.size[1]; ++j)
      for (int i = 0; i < image.size[0]; ++i)
        if (selected.count(image.at(i, j, k))) {
          const std::int64_t I = i / f[0] + 1, J = j / f[1] + 1, K = k / f[2] + 1;
          values[static_cast<std::size_t>(I + g.size[0] * (J + g.size[1] * K))] += per_block;
        }
  return g;
}

// The marching-cubes surface of the smoothed fractions at one half (ITK), as a surface-triangle mesh (m).
mesh::Mesh extract_surface(const detail::Grid& grid, const std::vector<float>& values, double sigma,
                           const std::string& source) {
  const detail::RawSurface raw = detail::itk_half_level_surface(grid, values, sigma);
  RowMatX x(static_cast<Eigen::Index>(raw.points.size()), 3);
  for (std::size_t i = 0; i < raw.points.size(); ++i)
    for (int a = 0; a < 3; ++a) x(static_cast<Eigen::Index>(i), a) = raw.points[i][static_cast<std::size_t>(a)];
  RowMatXi t(static_cast<Eigen::Index>(raw.triangles.size()), 3);
  for (std::size_t r = 0; r < raw.triangles.size(); ++r)
    for (int k = 0; k < 3; ++k) t(static_cast<Eigen::Index>(r), k) = raw.triangles[r][static_cast<std::size_t>(k)];
  return mesh::make_mesh(mesh::ElementKind::kSurfaceTriangle, std::move(x), std::move(t), source);
}

// The label of tet e: the most frequent selected label among its centroid and the midpoints towards its corners
// (then 20 more points spread inside it); -1 when none is selected.
int tet_label(const LabelImage& image, const std::set<int>& selected, const mesh::Mesh& m, int e) {
  Vec3 p[4];
  for (int k = 0; k < 4; ++k) p[k] = m.nodes.row(m.elements(e, k)).transpose();
  const Vec3 c = 0.25 * (p[0] + p[1] + p[2] + p[3]);
  std::map<int, int> votes;
  auto vote = [&](const Vec3& q) {
    const int l = image.label_at(q, 0);
    if (selected.count(l)) ++votes[l];
  };
  vote(c);
  vote(c);  // the centroid decides ties
  for (int k = 0; k < 4; ++k) vote(0.5 * (c + p[k]));
  if (votes.empty())
    for (int s = 1; s <= 20; ++s) {  // a low-discrepancy spread of barycentric weights
      const double a = std::fmod(0.618034 * s, 1.0), b = std::fmod(0.754878 * s, 1.0), d = std::fmod(0.569840 * s, 1.0);
      const double w0 = a * (1 - b), w1 = a * b * (1 - d), w2 = a * b * d, w3 = 1 - w0 - w1 - w2;
      vote(w0 * p[0] + w1 * p[1] + w2 * p[2] + w3 * p[3]);
    }
  if (votes.empty()) return -1;
  return std::max_element(votes.begin(), votes.end(), [](const auto& x, const auto& y) { return x.second < y.second; })
      ->first;
}

}  // namespace

std::string LabelMesh::summary() const {
  char line[256];
  std::snprintf(line, sizeof line, "%d tets, %d nodes from a surface of %d triangles (%d specks dropped, %.3g m^3)",
                tets.element_count(), tets.node_count(), surface_triangles, dropped_pieces, dropped_volume);
  std::string out = line;
  for (const LabelReport& r : labels) {
    std::snprintf(line, sizeof line, "; label %d: %lld voxels, %d tets, volume %+.2f %%", r.label,
                  static_cast<long long>(r.voxels), r.tets, 100.0 * r.volume_error);
    out += line;
  }
  std::snprintf(line, sizeof line, "; %.1f s", seconds);
  return out + line;
}

LabelMesh labels_to_mesh(const LabelImage& image, const LabelMeshOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (!(options.smoothing >= 0.0 && options.smoothing <= 10.0))
    throw InvalidArgument("the label smoothing (sigma in voxels) must be in [0, 10]");
  if (options.surface_smoothing < 0 || options.surface_smoothing > 1000)
    throw InvalidArgument("the surface smoothing iterations must be in [0, 1000]");
  const std::map<std::int32_t, std::int64_t> histogram = image.histogram();
  std::string present;
  for (const auto& [l, n] : histogram) present += (present.empty() ? "" : ", ") + std::to_string(l);
  std::set<int> selected;
  if (options.labels.empty()) {
    for (const auto& [l, n] : histogram)
      if (l != 0) selected.insert(l);
  } else {
    for (const int l : options.labels) {
      if (!histogram.count(l))
        throw InvalidArgument(image.source + " has no voxel of label " + std::to_string(l) +
                              " (its labels: " + present + ")");
      selected.insert(l);
    }
  }
  if (selected.empty()) throw InvalidArgument(image.source + " has no voxel of a label other than 0");
  // The selected voxels' bounding box sets the default size.
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (int k = 0; k < image.size[2]; ++k)
    for (int j = 0; j < image.size[1]; ++j)
      for (int i = 0; i < image.size[0]; ++i)
        if (selected.count(image.at(i, j, k))) {
          const Vec3 c = image.centre(i, j, k);
          lo = lo.cwiseMin(c);
          hi = hi.cwiseMax(c);
        }
  mesh::TetrahedralizeOptions tet = options.tetrahedralize;
  if (tet.max_size == 0.0) tet.max_size = (hi - lo + image.spacing).norm() / 25.0;
  if (!(tet.max_size > 0.0)) throw InvalidArgument("the tet size must be > 0 m");
  std::array<int, 3> f{};
  for (int a = 0; a < 3; ++a) f[a] = std::max(1, static_cast<int>(std::lround(0.5 * tet.max_size / image.spacing(a))));
  LabelMesh out;
  std::vector<float> fractions;
  const detail::Grid grid = block_fractions(image, selected, f, fractions);
  mesh::Mesh surface = extract_surface(grid, fractions, options.smoothing, image.source);
  fractions = {};
  surface = mesh::weld_surface(surface, &out.welded_nodes);
  mesh::taubin_smooth(surface, options.surface_smoothing);
  tet.surface = mesh::SurfaceMeshing::kKeep;
  try {
    out.tets = io::tetrahedralize(std::move(surface), tet, &out.meshing);
  } catch (const InvalidMesh& e) {
    throw InvalidMesh(image.source + ": the surface of labels could not be meshed: " + e.what(), -1);
  }
  out.tets.source = image.source;
  out.surface_triangles = out.meshing.surface_triangles;  // after the specks (tetrahedralize drops them)
  out.dropped_pieces = out.meshing.dropped_pieces;
  out.dropped_volume = out.meshing.dropped_volume;
  const int ne = out.tets.element_count();
  out.tets.region.resize(ne);
  const int fallback = *selected.begin();
  for (int e = 0; e < ne; ++e) {
    int l = tet_label(image, selected, out.tets, e);
    if (l < 0) {
      ++out.unlabelled_tets;
      l = fallback;
    }
    out.tets.region(e) = l;
  }
  std::map<int, LabelReport> by_label;  // one pass over the tets for every label's report
  for (const int l : selected) {
    LabelReport& r = by_label[l];
    r.label = l;
    r.voxels = histogram.at(l);
    r.voxel_volume = static_cast<double>(r.voxels) * image.voxel_volume();
    r.min_dihedral = 180.0;
  }
  for (int e = 0; e < ne; ++e) {
    LabelReport& r = by_label.at(out.tets.region(e));
    ++r.tets;
    r.volume += mesh::element_measure(out.tets, e);
    Vec3 p[4];
    for (int k = 0; k < 4; ++k) p[k] = out.tets.nodes.row(out.tets.elements(e, k)).transpose();
    for (const double angle : mesh::dihedral_angles(p[0], p[1], p[2], p[3]))
      r.min_dihedral = std::min(r.min_dihedral, angle);
  }
  for (auto& [l, r] : by_label) {
    r.volume_error = r.volume / r.voxel_volume - 1.0;
    out.labels.push_back(r);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

void register_label_image_reader() {
  io::MeshReader r;
  r.accepts = [](const std::filesystem::path& p) { return is_label_image_path(p); };
  r.read = [](const std::filesystem::path& p) {
    const LabelMesh m = labels_to_mesh(read_label_image(p));
    log(LogLevel::kInfo, p.string() + ": " + m.summary());
    return m.tets;
  };
  r.extensions = ".nii, .nii.gz, .nrrd, .nhdr, .mha, .mhd (label images)";
  io::register_mesh_reader(std::move(r));
}

}  // namespace hooke::image
