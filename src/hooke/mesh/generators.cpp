#include <hooke/mesh/generators.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/mesh/measure.hpp>
#include <map>
#include <numbers>
#include <vector>

namespace hooke::mesh {
namespace {

void require(bool ok, const char* what) {
  if (!ok) throw InvalidArgument(what);
}

RowMatXi to_rows(const std::vector<int>& flat, int cols) {
  RowMatXi m(static_cast<Eigen::Index>(flat.size()) / cols, cols);
  for (Eigen::Index i = 0; i < m.size(); ++i) m.data()[i] = flat[static_cast<size_t>(i)];
  return m;
}

RowMatX to_rows(const std::vector<double>& flat, int cols) {
  RowMatX m(static_cast<Eigen::Index>(flat.size()) / cols, cols);
  for (Eigen::Index i = 0; i < m.size(); ++i) m.data()[i] = flat[static_cast<size_t>(i)];
  return m;
}

}  // namespace

Mesh equilateral_membrane(int rows, int long_row, double edge) {
  require(rows >= 2 && long_row >= 2 && edge > 0.0, "equilateral_membrane: needs rows >= 2, long_row >= 2, edge > 0");
  const double dy = edge * std::sqrt(3.0) / 2.0;
  std::vector<double> xy;
  std::vector<int> first(rows + 1, 0);
  for (int r = 0; r < rows; ++r) {
    const bool is_long = r % 2 == 0;
    const int count = is_long ? long_row : long_row - 1;
    first[r] = static_cast<int>(xy.size() / 2);
    for (int c = 0; c < count; ++c) {
      xy.push_back((c + (is_long ? 0.0 : 0.5)) * edge);
      xy.push_back(r * dy);
    }
  }
  std::vector<int> tri;
  for (int r = 0; r + 1 < rows; ++r) {
    const int lo = first[r], hi = first[r + 1];
    if (r % 2 == 0) {  // long row below, short row above
      for (int c = 0; c + 1 < long_row; ++c) tri.insert(tri.end(), {lo + c, lo + c + 1, hi + c});
      for (int c = 0; c + 2 < long_row; ++c) tri.insert(tri.end(), {lo + c + 1, hi + c + 1, hi + c});
    } else {  // short row below, long row above
      for (int c = 0; c + 1 < long_row; ++c) tri.insert(tri.end(), {hi + c, lo + c, hi + c + 1});
      for (int c = 0; c + 2 < long_row; ++c) tri.insert(tri.end(), {lo + c, lo + c + 1, hi + c + 1});
    }
  }
  return make_mesh(ElementKind::kTriangle, to_rows(xy, 2), to_rows(tri, 3), "equilateral membrane");
}

Mesh hexagon_membrane(int rings, double side) {
  require(rings >= 1 && side > 0.0, "hexagon_membrane: needs rings >= 1, side > 0");
  const double h = side / rings;
  const Vec2 a1(h, 0.0), a2(h / 2.0, h * std::sqrt(3.0) / 2.0);
  std::map<std::pair<int, int>, int> id;
  std::vector<double> xy;
  auto inside = [&](int i, int j) { return std::abs(i) <= rings && std::abs(j) <= rings && std::abs(i + j) <= rings; };
  for (int j = -rings; j <= rings; ++j)
    for (int i = -rings; i <= rings; ++i)
      if (inside(i, j)) {
        id[{i, j}] = static_cast<int>(xy.size() / 2);
        const Vec2 p = i * a1 + j * a2;
        xy.push_back(p.x());
        xy.push_back(p.y());
      }
  std::vector<int> tri;
  for (int j = -rings; j <= rings; ++j)
    for (int i = -rings; i <= rings; ++i) {
      if (inside(i, j) && inside(i + 1, j) && inside(i, j + 1))
        tri.insert(tri.end(), {id[{i, j}], id[{i + 1, j}], id[{i, j + 1}]});
      if (inside(i + 1, j) && inside(i + 1, j + 1) && inside(i, j + 1))
        tri.insert(tri.end(), {id[{i + 1, j}], id[{i + 1, j + 1}], id[{i, j + 1}]});
    }
  return make_mesh(ElementKind::kTriangle, to_rows(xy, 2), to_rows(tri, 3), "hexagon membrane");
}

Mesh rectangle_quads(double width, double height, int nx, int ny) {
  require(nx >= 1 && ny >= 1 && width > 0.0 && height > 0.0, "rectangle_quads: needs nx, ny >= 1 and a positive size");
  std::vector<double> xy;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) xy.insert(xy.end(), {width * i / nx, height * j / ny});
  std::vector<int> quads;
  auto id = [&](int i, int j) { return i + (nx + 1) * j; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) quads.insert(quads.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return make_mesh(ElementKind::kQuad, to_rows(xy, 2), to_rows(quads, 4), "rectangle (quads)");
}

Mesh rectangle_triangles(double width, double height, int nx, int ny, Diagonal diagonal) {
  Mesh quads = rectangle_quads(width, height, nx, ny);
  std::vector<int> tri;
  for (int e = 0; e < quads.element_count(); ++e) {
    const auto q = quads.elements.row(e);
    const int i = e % nx, j = e / nx;
    const bool rising = diagonal == Diagonal::kRising || (diagonal == Diagonal::kAlternating && (i + j) % 2 == 0);
    if (rising) {
      tri.insert(tri.end(), {q(0), q(1), q(2), q(0), q(2), q(3)});
    } else {
      tri.insert(tri.end(), {q(0), q(1), q(3), q(1), q(2), q(3)});
    }
  }
  return make_mesh(ElementKind::kTriangle, std::move(quads.nodes), to_rows(tri, 3), "rectangle (triangles)");
}

Mesh tet_box(double lx, double ly, double lz, int nx, int ny, int nz) {
  require(nx >= 1 && ny >= 1 && nz >= 1 && lx > 0.0 && ly > 0.0 && lz > 0.0,
          "tet_box: needs nx, ny, nz >= 1 and a positive size");
  std::vector<double> xyz;
  xyz.reserve(static_cast<size_t>(3) * (nx + 1) * (ny + 1) * (nz + 1));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) xyz.insert(xyz.end(), {lx * i / nx, ly * j / ny, lz * k / nz});
  auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  static constexpr int kPerm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::vector<int> tets;
  tets.reserve(static_cast<size_t>(24) * nx * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        auto corner = [&](int bits) { return id(i + (bits & 1), j + ((bits >> 1) & 1), k + ((bits >> 2) & 1)); };
        for (const auto& p : kPerm) {
          const int b1 = 1 << p[0], b2 = b1 | (1 << p[1]);
          // Even permutations of the axes give positive tets in this node order, odd ones negative.
          const bool even = (p[0] + 1) % 3 == p[1];
          if (even) {
            tets.insert(tets.end(), {corner(0), corner(b1), corner(b2), corner(7)});
          } else {
            tets.insert(tets.end(), {corner(0), corner(b2), corner(b1), corner(7)});
          }
        }
      }
  return make_mesh(ElementKind::kTet, to_rows(xyz, 3), to_rows(tets, 4), "tet box");
}

namespace {

// The cross-section of tet_cylinder: an O-grid of the disc of `radius` (a square of m x m cells in the middle, a
// ring of k cells between it and the circle), each quad split along its shorter diagonal into two
// counter-clockwise triangles. Nodes: the square row by row, then ring by ring.
void disc_triangles(double radius, int m, int k, std::vector<double>& xy, std::vector<int>& tri) {
  const double s = radius * m / (m + 2.0 * k);  // inner half-width: square cells as deep as the ring's at mid-edge
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) xy.insert(xy.end(), {s * (2.0 * i / m - 1.0), s * (2.0 * j / m - 1.0)});
  auto square = [&](int i, int j) { return i + (m + 1) * j; };
  // Boundary of the square, counter-clockwise from (-s, -s): position b in [0, 4m).
  auto boundary = [&](int b) {
    const int side = b / m, t = b % m;
    switch (side) {
      case 0: return square(t, 0);
      case 1: return square(m, t);
      case 2: return square(m - t, m);
      default: return square(0, m - t);
    }
  };
  const int around = 4 * m, first_ring = (m + 1) * (m + 1);
  auto ring = [&](int b, int j) { return j == 0 ? boundary(b % around) : first_ring + (j - 1) * around + b % around; };
  for (int j = 1; j <= k; ++j)
    for (int b = 0; b < around; ++b) {
      const int q = boundary(b);
      const double angle = -0.75 * std::numbers::pi + 2.0 * std::numbers::pi * b / around;  // corners at 45 deg
      const double t = static_cast<double>(j) / k, x = xy[2 * static_cast<size_t>(q)],
                   y = xy[2 * static_cast<size_t>(q) + 1];
      xy.insert(xy.end(), {(1.0 - t) * x + t * radius * std::cos(angle), (1.0 - t) * y + t * radius * std::sin(angle)});
    }
  auto quad = [&](int a, int b, int c, int d) {  // counter-clockwise
    auto len2 = [&](int p, int q) {
      const double dx = xy[2 * static_cast<size_t>(p)] - xy[2 * static_cast<size_t>(q)];
      const double dy = xy[2 * static_cast<size_t>(p) + 1] - xy[2 * static_cast<size_t>(q) + 1];
      return dx * dx + dy * dy;
    };
    if (len2(a, c) <= len2(b, d))
      tri.insert(tri.end(), {a, b, c, a, c, d});
    else
      tri.insert(tri.end(), {a, b, d, b, c, d});
  };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) quad(square(i, j), square(i + 1, j), square(i + 1, j + 1), square(i, j + 1));
  for (int j = 0; j < k; ++j)
    for (int b = 0; b < around; ++b) quad(ring(b, j), ring(b, j + 1), ring(b + 1, j + 1), ring(b + 1, j));
}

// The three tets of the prism over triangle (a, b, c) with top (d, e, f): every quadrilateral face is cut along
// the diagonal through its smallest node index, which makes neighbouring prisms conform and always leaves a
// split into three tets (Dompierre et al. 1999, "How to subdivide pyramids, prisms and hexahedra into
// tetrahedra"). Each tet is oriented positively by the caller.
void prism_tets(std::array<int, 6> v, std::vector<int>& tets) {
  // Rotate / flip so that the smallest index is v[0] (bottom a), keeping (a, b, c) / (d, e, f) a prism.
  static constexpr int kSym[6][6] = {{0, 1, 2, 3, 4, 5}, {1, 2, 0, 4, 5, 3}, {2, 0, 1, 5, 3, 4},
                                     {3, 5, 4, 0, 2, 1}, {4, 3, 5, 1, 0, 2}, {5, 4, 3, 2, 1, 0}};
  const int lowest = static_cast<int>(std::min_element(v.begin(), v.end()) - v.begin());
  std::array<int, 6> p{};
  for (int q = 0; q < 6; ++q) p[static_cast<size_t>(q)] = v[static_cast<size_t>(kSym[lowest][q])];
  const int a = p[0], b = p[1], c = p[2], d = p[3], e = p[4], f = p[5];
  if (std::min(b, f) < std::min(c, e))
    tets.insert(tets.end(), {a, b, c, f, a, b, f, e, a, e, f, d});
  else
    tets.insert(tets.end(), {a, b, c, e, a, e, c, f, a, e, f, d});
}

}  // namespace

Mesh tet_cylinder(double radius, double height, int n, int layers) {
  require(n >= 2 && n % 2 == 0 && layers >= 1 && radius > 0.0 && height > 0.0,
          "tet_cylinder: needs an even n >= 2, layers >= 1 and a positive size");
  std::vector<double> xy;
  std::vector<int> tri;
  disc_triangles(radius, n / 2, std::max(1, n / 4), xy, tri);
  const int per_level = static_cast<int>(xy.size() / 2);
  std::vector<double> xyz;
  for (int l = 0; l <= layers; ++l)
    for (int i = 0; i < per_level; ++i)
      xyz.insert(xyz.end(), {xy[2 * static_cast<size_t>(i)], xy[2 * static_cast<size_t>(i) + 1], height * l / layers});
  std::vector<int> tets;
  for (int l = 0; l < layers; ++l)
    for (size_t t = 0; t < tri.size(); t += 3) {
      const int lo = l * per_level, hi = (l + 1) * per_level;
      prism_tets({lo + tri[t], lo + tri[t + 1], lo + tri[t + 2], hi + tri[t], hi + tri[t + 1], hi + tri[t + 2]}, tets);
    }
  Mesh m = make_mesh(ElementKind::kTet, to_rows(xyz, 3), to_rows(tets, 4), "tet cylinder");
  for (int e = 0; e < m.element_count(); ++e)  // orient every tet positively
    if (element_measure(m, e) < 0.0) std::swap(m.elements(e, 2), m.elements(e, 3));
  return m;
}

Mesh cube_surface(int n, double size) {
  require(n >= 1 && size > 0.0, "cube_surface: needs n >= 1 and size > 0");
  std::map<std::array<int, 3>, int> id;
  std::vector<double> xyz;
  auto node = [&](std::array<int, 3> c) {
    auto [it, inserted] = id.try_emplace(c, static_cast<int>(xyz.size() / 3));
    if (inserted)
      for (int a = 0; a < 3; ++a) xyz.push_back(size * c[static_cast<size_t>(a)] / n);
    return it->second;
  };
  std::vector<int> tri;
  for (int d = 0; d < 3; ++d) {
    const int u = (d + 1) % 3, v = (d + 2) % 3;  // (u, v, d) right-handed
    for (int side = 0; side <= 1; ++side) {
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          auto at = [&](int da, int db) {
            std::array<int, 3> c{};
            c[static_cast<size_t>(d)] = side * n;
            c[static_cast<size_t>(u)] = a + da;
            c[static_cast<size_t>(v)] = b + db;
            return node(c);
          };
          const int p00 = at(0, 0), p10 = at(1, 0), p11 = at(1, 1), p01 = at(0, 1);
          if (side == 1) {
            tri.insert(tri.end(), {p00, p10, p11, p00, p11, p01});
          } else {
            tri.insert(tri.end(), {p00, p11, p10, p00, p01, p11});
          }
        }
    }
  }
  return make_mesh(ElementKind::kSurfaceTriangle, to_rows(xyz, 3), to_rows(tri, 3), "cube surface");
}

Mesh uv_sphere_surface(int rings, int segments, double radius) {
  if (rings < 2 || segments < 3 || !(radius > 0.0))
    throw InvalidArgument("uv_sphere_surface: rings >= 2, segments >= 3 and radius > 0 required");
  std::vector<double> xyz{0.0, 0.0, radius};
  for (int r = 1; r < rings; ++r) {
    const double theta = std::numbers::pi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * std::numbers::pi * s / segments;
      xyz.insert(xyz.end(), {radius * std::sin(theta) * std::cos(phi), radius * std::sin(theta) * std::sin(phi),
                             radius * std::cos(theta)});
    }
  }
  xyz.insert(xyz.end(), {0.0, 0.0, -radius});
  const int south = 1 + (rings - 1) * segments;
  auto at = [&](int r, int s) { return 1 + (r - 1) * segments + (s % segments); };  // r in 1 .. rings-1
  std::vector<int> tri;
  for (int s = 0; s < segments; ++s) {
    tri.insert(tri.end(), {0, at(1, s), at(1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r)
      tri.insert(tri.end(), {at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s), at(r + 1, s + 1), at(r, s + 1)});
    tri.insert(tri.end(), {at(rings - 1, s), south, at(rings - 1, s + 1)});
  }
  return make_mesh(ElementKind::kSurfaceTriangle, to_rows(xyz, 3), to_rows(tri, 3), "uv sphere");
}

Mesh tetrahedralise_radially(const Mesh& surface, const Vec3& centre, int layers) {
  if (surface.kind != ElementKind::kSurfaceTriangle || layers < 1)
    throw InvalidArgument("tetrahedralise_radially needs a triangle surface and layers >= 1");
  const int n = surface.node_count();
  RowMatX nodes(1 + layers * n, 3);
  nodes.row(0) = centre.transpose();
  for (int k = 1; k <= layers; ++k)
    for (int i = 0; i < n; ++i)
      nodes.row(1 + (k - 1) * n + i) = centre.transpose() + (surface.nodes.row(i) - centre.transpose()) * k / layers;
  auto at = [&](int k, int i) { return 1 + (k - 1) * n + i; };  // layer k >= 1
  std::vector<std::array<int, 4>> tets;
  for (int t = 0; t < surface.element_count(); ++t) {
    std::array<int, 3> v{surface.elements(t, 0), surface.elements(t, 1), surface.elements(t, 2)};
    tets.push_back({0, at(1, v[0]), at(1, v[1]), at(1, v[2])});
    std::sort(v.begin(), v.end());  // the diagonal of each side face then runs the same way in both prisms
    for (int k = 1; k < layers; ++k) {
      const int i0 = at(k, v[0]), j0 = at(k, v[1]), k0 = at(k, v[2]);
      const int i1 = at(k + 1, v[0]), j1 = at(k + 1, v[1]), k1 = at(k + 1, v[2]);
      tets.push_back({i0, j0, k0, i1});
      tets.push_back({j0, k0, i1, j1});
      tets.push_back({k0, i1, j1, k1});
    }
  }
  RowMatXi elements(static_cast<Eigen::Index>(tets.size()), 4);
  for (size_t e = 0; e < tets.size(); ++e) {
    auto& q = tets[e];
    const auto p = [&](int a) { return Vec3(nodes.row(q[static_cast<size_t>(a)]).transpose()); };
    if (signed_volume(p(0), p(1), p(2), p(3)) < 0.0) std::swap(q[2], q[3]);
    elements.row(static_cast<Eigen::Index>(e)) << q[0], q[1], q[2], q[3];
  }
  return make_mesh(ElementKind::kTet, std::move(nodes), std::move(elements), "radial tetrahedralisation");
}

}  // namespace hooke::mesh
