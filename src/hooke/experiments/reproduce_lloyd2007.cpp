#include <chrono>
#include <cmath>
#include <hooke/core/log.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/experiments/reproduce_lloyd2007.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/mesh/generators.hpp>
#include <hooke/solve/strain_response.hpp>
#include <set>

namespace hooke::experiments {
namespace {

constexpr double kE = 14630.0;  // Pa, Lloyd Sec. 5 (liver, [12])
constexpr const char* kLoads[3] = {"stretch", "compress", "shear"};

struct Spec {
  std::string id, section, figure, mesh_name, method, load, reference;
  double strain = 0.12;
  double paper_max = -1.0, paper_mean = -1.0;
  std::string fit_method;  // run beside it, or ""
};

bool converged(const Comparison& c) {
  return c.fem_report.status == solve::SolveStatus::kConverged &&
         c.spring_report.status == solve::SolveStatus::kConverged;
}

Lloyd2007Case describe(const mesh::Mesh& m, const Spec& s, const Comparison& r) {
  Lloyd2007Case c;
  c.id = s.id;
  c.section = s.section;
  c.figure = s.figure;
  c.mesh = s.mesh_name;
  c.method = s.method;
  c.load = s.load;
  c.reference = s.reference;
  c.strain = s.strain;
  c.nodes = m.node_count();
  c.elements = m.element_count();
  c.paper_max_cm = s.paper_max;
  c.paper_mean_cm = s.paper_mean;
  c.fit_method = s.fit_method;
  c.springs = static_cast<int>(r.springs.pairs.size());
  const bool fem_ok = r.fem_report.status == solve::SolveStatus::kConverged;
  const solve::SolveReport& failed = fem_ok ? r.spring_report : r.fem_report;
  c.status = converged(r) ? "converged"
                          : std::string(fem_ok ? "springs " : "fem ") + std::string(solve::status_name(failed.status));
  if (!converged(r)) c.message = failed.message;
  if (converged(r)) {
    c.max_error_cm = 100.0 * r.max_error;
    c.mean_error_cm = 100.0 * r.mean_error;
  }
  return c;
}

CompareOptions options(const Spec& s, const std::string& method) {
  CompareOptions o;
  o.method = calibrate::method_from_name(method);
  o.load = model::load_kind_from_name(s.load);
  o.reference = material::law_from_name(s.reference);
  o.strain = s.strain;
  return o;
}

class Runner {
 public:
  Lloyd2007Report report;

  // Runs one case (and its fit counterpart); returns the deformation panel of the case.
  DeformationPanel run(const mesh::Mesh& m, const std::vector<material::Material>& mats, const Spec& s) {
    const Comparison r = compare(m, mats, options(s, s.method));
    return add(m, m, s, r, [&](const std::string& fit) { return compare(m, mats, options(s, fit)); });
  }

  // A spring model on `coarse` against the FEM on `fine` (Sec. 5.4).
  DeformationPanel run_across(const mesh::Mesh& coarse, const mesh::Mesh& fine, const material::Material& mat,
                              const Spec& s) {
    const Comparison r = compare_across(coarse, fine, mat, options(s, s.method));
    return add(coarse, fine, s, r,
               [&](const std::string& fit) { return compare_across(coarse, fine, mat, options(s, fit)); });
  }

  // A given spring model (a variant no method names).
  DeformationPanel run_model(const mesh::Mesh& m, const std::vector<material::Material>& mats,
                             const calibrate::SpringModel& springs, const Spec& s) {
    // compare_model ignores the options' method; any valid name fills it.
    const Comparison r = compare_model(m, mats, springs, options(s, "stiffness-fit"));
    return add(m, m, s, r, [&](const std::string&) { return r; });
  }

  void figure(std::string name, std::string title, std::vector<DeformationPanel> panels) {
    Figure f{std::move(name), std::move(title), {}};
    for (auto& p : panels) f.panels.emplace_back(std::move(p));
    report.figures.push_back(std::move(f));
  }

 private:
  template <typename Fit>
  DeformationPanel add(const mesh::Mesh& m, const mesh::Mesh& fem_mesh, const Spec& s, const Comparison& r, Fit&& fit) {
    Lloyd2007Case c = describe(m, s, r);
    if (!s.fit_method.empty()) {
      const Comparison f = fit(s.fit_method);
      if (converged(f)) {
        c.fit_max_error_cm = 100.0 * f.max_error;
        c.fit_mean_error_cm = 100.0 * f.mean_error;
      }
    }
    std::string title = s.load + " (" + s.method + ")";
    if (c.max_error_cm >= 0.0) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "\nmax %.3f cm, mean %.3f cm", c.max_error_cm, c.mean_error_cm);
      title += buf;
    } else {
      title += "\n" + c.status;
    }
    report.cases.push_back(std::move(c));
    return deformation_panel(title, fem_mesh, r.fem_mesh_positions, m, r.spring_positions);
  }
};

// Fig. 1: an equilateral triangle (Eq. 8) and a square (Eq. 10-11), edge 1 m, clamped at the bottom edge,
// loaded at the top node(s); forces up to +-0.24 E t (linear top displacements up to about 40 % of the height;
// the compressed triangle snaps through before the end of the range, those points are left out).
void figure1(Runner& run) {
  const material::Material mat{material::Law::kLinear, 1000.0, 1.0 / 3.0, material::Plane::kStress, 0.01};
  std::vector<double> forces;
  for (int i = -10; i <= 10; ++i)
    if (i != 0) forces.push_back(0.024 * i * mat.youngs_modulus * mat.thickness);
  run.report.triangle =
      force_displacement(mesh::equilateral_membrane(2, 2, 1.0), mat, calibrate::Method::kLloydEquilateral, forces);
  run.report.square =
      force_displacement(mesh::rectangle_quads(1.0, 1.0, 1, 1), mat, calibrate::Method::kLloydSquare, forces);
  Figure f{"fig01_force_displacement", "Fig. 1: force-displacement non-linearity of mass-spring models", {}};
  for (const auto* fd : {&run.report.triangle, &run.report.square}) {
    CurvePanel p;
    p.title = fd == &run.report.triangle ? "(a) equilateral triangle, Eq. 8" : "(b) square, Eq. 10-11";
    p.xlabel = "displacement of the top node(s), m";
    p.ylabel = "force per top node, N";
    Series msm{"MSM (computed)", "ro", {}, {}}, fem{"linear FEM", "k-", {}, {}}, st{"fit, stretch", "b--", {}, {}},
        co{"fit, compression", "g--", {}, {}};
    double umin = 0.0, umax = 0.0;
    for (size_t i = 0; i < fd->force.size(); ++i) {
      fem.x.push_back(fd->fem_displacement[i]);
      fem.y.push_back(fd->force[i]);
      if (!std::isfinite(fd->spring_displacement[i])) continue;
      msm.x.push_back(fd->spring_displacement[i]);
      msm.y.push_back(fd->force[i]);
      umin = std::min(umin, fd->spring_displacement[i]);
      umax = std::max(umax, fd->spring_displacement[i]);
    }
    st.x = {0.0, umax};
    st.y = {0.0, fd->stretch_stiffness * umax};
    co.x = {umin, 0.0};
    co.y = {fd->compress_stiffness * umin, 0.0};
    p.series = {msm, st, co, fem};
    f.panels.emplace_back(p);
  }
  run.report.figures.push_back(std::move(f));
}

// Fig. 3: the Eq. 8 hexagon (1.7 cm high) against the FEM for nu from 0 to 0.49, at the traction that gives
// 12 % (compression: 6 %) in the nu = 1/3 FEM (so the spring model is the same for every nu, only the reference
// changes).
void figure3(Runner& run) {
  const double side = 0.017 / std::sqrt(3.0);
  const mesh::Mesh hex = mesh::hexagon_membrane(4, side);
  material::Material mat{material::Law::kLinear, kE, 1.0 / 3.0, material::Plane::kStress, 0.001};
  Figure f{"fig03_error_vs_nu", "Fig. 3: hexagon (1.7 cm high, equilateral triangles), Eq. 8 springs vs FEM", {}};
  for (const char* load : kLoads) {
    CompareOptions o;
    o.load = model::load_kind_from_name(load);
    // Compression at 6 %: at 12 % the clamped Eq. 8 hexagon passes its limit load.
    const double strain = o.load == model::LoadKind::kCompress ? 0.06 : 0.12;
    o.traction_pa = solve::traction_for_strain(hex, {mat}, o.load, strain);
    CurvePanel p{std::string(load) + (strain < 0.1 ? " (6 %" : " (12 %") + " at nu = 1/3)",
                 "Poisson's ratio nu",
                 "node distance error, cm",
                 {}};
    Series mx{"max, Eq. 8", "ro-", {}, {}}, mn{"mean, Eq. 8", "bs-", {}, {}}, fmx{"max, stiffness-fit", "r^:", {}, {}},
        fmn{"mean, stiffness-fit", "b^:", {}, {}};
    for (double nu : {0.0, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 1.0 / 3.0, 0.35, 0.4, 0.45, 0.49}) {
      mat.poisson_ratio = nu;
      NuPoint pt;
      pt.nu = nu;
      pt.load = load;
      o.method = calibrate::Method::kLloydEquilateral;
      const Comparison a = compare(hex, {mat}, o);
      o.method = calibrate::Method::kStiffnessFit;
      const Comparison b = compare(hex, {mat}, o);
      // Records a comparison's errors (cm) into the point and the two series when it converged.
      auto record = [nu](const Comparison& c, double& max_cm, double& mean_cm, Series& smax, Series& smean) {
        if (!converged(c)) return;
        max_cm = 100.0 * c.max_error;
        mean_cm = 100.0 * c.mean_error;
        smax.x.push_back(nu);
        smax.y.push_back(max_cm);
        smean.x.push_back(nu);
        smean.y.push_back(mean_cm);
      };
      record(a, pt.max_error_cm, pt.mean_error_cm, mx, mn);
      record(b, pt.fit_max_error_cm, pt.fit_mean_error_cm, fmx, fmn);
      run.report.nu_sweep.push_back(pt);
    }
    p.series = {mx, mn, fmx, fmn};
    f.panels.emplace_back(p);
  }
  run.report.figures.push_back(std::move(f));
}

}  // namespace

Lloyd2007Report reproduce_lloyd2007(const std::filesystem::path& mesh_dir) {
  const auto start = std::chrono::steady_clock::now();
  Runner run;
  // The experiments apply methods outside their derivation on purpose (Fig. 3, Sec. 5.2): collect the
  // validity warnings once each for the report instead of printing them per case.
  std::set<std::string> warnings;
  struct Restore {
    LogSink previous;
    ~Restore() { set_log_sink(std::move(previous)); }
  } restore{set_log_sink([&warnings](LogLevel level, std::string_view message) {
    if (level == LogLevel::kWarning) warnings.emplace(message);
  })};
  const material::Material third{material::Law::kLinear, kE, 1.0 / 3.0, material::Plane::kStress, 0.001};
  const material::Material quarter{material::Law::kLinear, kE, 0.25};
  std::vector<DeformationPanel> panels;

  // Sec. 5.1, Fig. 9: equilateral membrane, 39 nodes, 92 springs, 5.2 cm high.
  const mesh::Mesh membrane = mesh::equilateral_membrane(7, 6, 0.01);
  const double p51[3][2] = {{0.033, 0.008}, {0.061, 0.012}, {0.098, 0.034}};
  for (int k = 0; k < 3; ++k)
    panels.push_back(run.run(membrane, {third},
                             {"sec5.1-membrane-" + std::string(kLoads[k]), "5.1", "Fig. 9", "equilateral membrane",
                              "lloyd-equilateral", kLoads[k], "linear", 0.12, p51[k][0], p51[k][1], "stiffness-fit"}));
  run.figure("fig09_membrane", "Sec. 5.1, Fig. 9: equilateral membrane, Eq. 8 (MSM red, FEM black)", std::move(panels));

  // Sec. 5.2, Fig. 10-11: a rectangle meshed with unstructured triangles, Eq. 8 against Eq. 9 (13.5 %), and
  // compression at 6 %: at 13.5 % the clamped spring model passes its limit load.
  const mesh::Mesh rect = io::read_mesh(mesh_dir / "rectangle_tri.msh");
  for (const bool eq9 : {false, true}) {
    const std::string method = eq9 ? "lloyd-triangle" : "lloyd-equilateral", tag = eq9 ? "eq9-" : "eq8-";
    panels.clear();
    for (const char* load : kLoads)
      panels.push_back(
          run.run(rect, {third},
                  {"sec5.2-triangles-" + tag + load, "5.2", eq9 ? "Fig. 11" : "Fig. 10",
                   "unstructured triangles 4 x 5 cm", method, load, "linear", 0.135, -1.0, -1.0, "stiffness-fit"}));
    panels.push_back(
        run.run(rect, {third},
                {"sec5.2-triangles-" + tag + "compress-6pct", "5.2", eq9 ? "Fig. 11" : "Fig. 10",
                 "unstructured triangles 4 x 5 cm", method, "compress", "linear", 0.06, -1.0, -1.0, "stiffness-fit"}));
    run.figure(eq9 ? "fig11_triangles_eq9" : "fig10_triangles_eq8",
               std::string("Sec. 5.2: unstructured triangles, ") + (eq9 ? "Eq. 9" : "Eq. 8"), std::move(panels));
  }

  // Sec. 5.3, Fig. 12: 5 x 5 cm square mesh, 36 nodes, 110 springs.
  const mesh::Mesh squares = mesh::rectangle_quads(0.05, 0.05, 5, 5);
  const double p53[3][2] = {{0.076, 0.041}, {0.129, 0.0677}, {0.196, 0.066}};
  panels.clear();
  for (int k = 0; k < 3; ++k)
    panels.push_back(run.run(squares, {third},
                             {"sec5.3-squares-" + std::string(kLoads[k]), "5.3", "Fig. 12", "5 x 5 squares",
                              "lloyd-square", kLoads[k], "linear", 0.12, p53[k][0], p53[k][1], "stiffness-fit"}));
  run.figure("fig12_squares", "Sec. 5.3, Fig. 12: 5 x 5 squares, Eq. 10-11", std::move(panels));

  // Sec. 5.4, Fig. 13: the 5 x 5 cm object at 4, 25 and 361 squares against the FEM at the finest resolution.
  const mesh::Mesh fine = mesh::rectangle_quads(0.05, 0.05, 19, 19);
  const double p54[3][2] = {{0.082, 0.036}, {0.087, 0.033}, {0.078, 0.024}};
  for (const char* load : kLoads) {
    panels.clear();
    int k = 0;
    for (int n : {2, 5, 19}) {
      const bool shear = std::string(load) == "shear";
      panels.push_back(
          run.run_across(mesh::rectangle_quads(0.05, 0.05, n, n), fine, third,
                         {"sec5.4-resolution-" + std::to_string(n * n) + "-" + load, "5.4", "Fig. 13",
                          std::to_string(n * n) + " squares (FEM: 361 squares)", "lloyd-square", load, "linear", 0.12,
                          shear ? p54[k][0] : -1.0, shear ? p54[k][1] : -1.0, "stiffness-fit"}));
      ++k;
    }
    run.figure("fig13_resolution_" + std::string(load),
               std::string("Sec. 5.4, Fig. 13: 4, 25, 361 squares, ") + load + ", FEM at 361 squares",
               std::move(panels));
  }

  // Sec. 5.5, Fig. 14: two-layer plate, 49 nodes, 156 springs. The text gives the top half 40 kPa and the
  // bottom 4 kPa; the caption calls the top layer the softer one. Both readings are run.
  const mesh::Mesh plate = mesh::rectangle_quads(0.05, 0.05, 6, 6);
  for (const bool caption : {false, true}) {
    std::vector<material::Material> layers(static_cast<size_t>(plate.element_count()), third);
    for (int e = 0; e < plate.element_count(); ++e)
      layers[static_cast<size_t>(e)].youngs_modulus = ((e / 6 >= 3) != caption) ? 40000.0 : 4000.0;
    panels.clear();
    for (const char* load : kLoads)
      panels.push_back(
          run.run(plate, layers,
                  {std::string("sec5.5-two-layer-") + (caption ? "caption-" : "text-") + load, "5.5", "Fig. 14",
                   caption ? "two-layer plate, top 4 kPa (caption)" : "two-layer plate, top 40 kPa (text)",
                   "lloyd-square", load, "linear", 0.12, -1.0, -1.0, "stiffness-fit"}));
    panels.push_back(
        run.run(plate, layers,
                {std::string("sec5.5-two-layer-") + (caption ? "caption-" : "text-") + "compress-6pct", "5.5",
                 "Fig. 14", caption ? "two-layer plate, top 4 kPa (caption)" : "two-layer plate, top 40 kPa (text)",
                 "lloyd-square", "compress", "linear", 0.06, -1.0, -1.0, "stiffness-fit"}));
    run.figure(caption ? "fig14_two_layer_caption" : "fig14_two_layer_text",
               caption ? "Sec. 5.5, Fig. 14 (caption's reading): top 4 kPa, bottom 40 kPa"
                       : "Sec. 5.5, Fig. 14 (text's reading): top 40 kPa, bottom 4 kPa",
               std::move(panels));
  }

  // Sec. 5.6 and 5.8, Fig. 15, 16, 18: cylinders with Eq. 12 and Eq. 14, plus compression at 6 %.
  const mesh::Mesh cylinder = io::read_mesh(mesh_dir / "cylinder.msh");
  const mesh::Mesh hole = io::read_mesh(mesh_dir / "cylinder_hole.msh");
  struct Solid {
    const mesh::Mesh* mesh;
    std::string key, section, figure, name, method, fit, file;
    double paper[3][2];
  };
  const Solid solids[3] = {{&cylinder,
                            "sec5.6-cylinder-",
                            "5.6",
                            "Fig. 15",
                            "cylinder r 1 cm, h 2 cm",
                            "lloyd-tet",
                            "stiffness-fit",
                            "fig15_cylinder",
                            {{0.039, 0.013}, {0.111, 0.025}, {0.088, 0.029}}},
                           {&hole,
                            "sec5.6-hole-",
                            "5.6",
                            "Fig. 16",
                            "cylinder with spherical hole",
                            "lloyd-tet",
                            "stiffness-fit",
                            "fig16_cylinder_hole",
                            {{0.039, 0.012}, {0.065, 0.013}, {0.100, 0.035}}},
                           {&cylinder,
                            "sec5.8-cylinder-volume-",
                            "5.8",
                            "Fig. 18",
                            "cylinder r 1 cm, h 2 cm",
                            "lloyd-tet-volume",
                            "stiffness-fit-volume",
                            "fig18_cylinder_volume",
                            {{0.029, 0.009}, {0.073, 0.018}, {0.183, 0.080}}}};
  for (const Solid& s : solids) {
    panels.clear();
    for (int k = 0; k < 3; ++k)
      panels.push_back(run.run(*s.mesh, {quarter},
                               {s.key + kLoads[k], s.section, s.figure, s.name, s.method, kLoads[k], "linear", 0.12,
                                s.paper[k][0], s.paper[k][1], s.fit}));
    // Compression at half the load, where the clamped objects are stable.
    panels.push_back(run.run(*s.mesh, {quarter},
                             {s.key + "compress-6pct", s.section, s.figure, s.name, s.method, "compress", "linear",
                              0.06, -1.0, -1.0, s.fit}));
    run.figure(s.file, "Sec. " + s.section + ", " + s.figure + ": " + s.name + ", " + s.method + " (y-z projection)",
               std::move(panels));
  }

  // Sec. 5.7, Fig. 17: cone under large shear against linear and StVK references.
  const mesh::Mesh cone = io::read_mesh(mesh_dir / "cone.msh");
  panels.clear();
  for (const char* ref : {"linear", "stvk"})
    panels.push_back(run.run(cone, {quarter},
                             {std::string("sec5.7-cone-shear-") + ref, "5.7", "Fig. 17", "truncated cone", "lloyd-tet",
                              "shear", ref, 0.3, -1.0, -1.0, "stiffness-fit"}));
  run.figure("fig17_cone", "Sec. 5.7, Fig. 17: cone, 30 % shear, against linear and StVK FEM", std::move(panels));

  // Evidence for the deviations from the paper's numbers (see the report's notes).
  for (const char* load : {"stretch", "compress"})
    for (double strain : {0.03, 0.06, 0.09})
      run.run(
          membrane, {third},
          {"evidence-membrane-" + std::string(load) + "-" +
               std::to_string(static_cast<int>(std::lround(strain * 100))) + "pct",
           "evidence", "Fig. 9", "equilateral membrane", "lloyd-equilateral", load, "linear", strain, -1.0, -1.0, ""});
  for (double strain : {0.18, 0.24})
    run.run(
        membrane, {third},
        {"evidence-membrane-shear-" + std::to_string(static_cast<int>(std::lround(strain * 100))) + "pct", "evidence",
         "Fig. 9", "equilateral membrane", "lloyd-equilateral", "shear", "linear", strain, -1.0, -1.0, ""});
  run.run(hole, {quarter},
          {"evidence-hole-shear-18pct", "evidence", "Fig. 16", "cylinder with spherical hole", "lloyd-tet", "shear",
           "linear", 0.18, -1.0, -1.0, ""});
  run.run(squares, {third},
          {"evidence-squares-shear-24pct", "evidence", "Fig. 12", "5 x 5 squares", "lloyd-square", "shear", "linear",
           0.24, -1.0, -1.0, ""});
  calibrate::SpringModel plain = calibrate::calibrate(squares, {third}, calibrate::Method::kLloydSquare);
  for (size_t s = 0; s < plain.pairs.size(); ++s)
    plain.rest_length(static_cast<Eigen::Index>(s)) =
        (squares.nodes.row(plain.pairs[s][0]) - squares.nodes.row(plain.pairs[s][1])).norm();
  for (const char* load : kLoads)
    run.run_model(squares, {third}, plain,
                  {std::string("evidence-squares-no-prestrain-") + load, "evidence", "Fig. 12", "5 x 5 squares",
                   "Eq. 10 without the prestrain of Eq. 11", load, "linear", 0.12, -1.0, -1.0, ""});

  figure1(run);
  figure3(run);
  run.report.warnings.assign(warnings.begin(), warnings.end());
  run.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return std::move(run.report);
}

}  // namespace hooke::experiments
