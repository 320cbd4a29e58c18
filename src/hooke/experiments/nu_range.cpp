#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/blas_threads.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/experiments/nu_range.hpp>
#include <hooke/experiments/term_law_fit.hpp>
#include <hooke/io/mesh_io.hpp>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

namespace hooke::experiments {
namespace {

struct Regime {
  std::string reference;
  double strain;
  std::string label() const {
    std::ostringstream s;
    s << strain * 100.0 << " % strain, " << reference << " FEM";
    return s.str();
  }
};

std::vector<Regime> regimes(const NuRangeOptions& o) {
  std::vector<Regime> out{{"linear", o.small_strain}};
  if (o.large_strain > 0.0) {
    out.push_back({"linear", o.large_strain});
    out.push_back({"stvk", o.large_strain});
  }
  return out;
}

// A task's mesh in its 2D reduction (tets: none): the table it belongs to and the methods run on it.
struct Unit {
  std::string table;  // calibrate::method_table_name
  std::string label;  // the mesh, with its plane for triangles
  const std::vector<std::string>* methods = nullptr;
};

Unit unit_of(const mesh::Mesh& mesh, const NuRangeOptions& o, const NuRangeTask& t) {
  if (mesh.kind == mesh::ElementKind::kTet) return {"tet", t.mesh, &o.methods};
  if (mesh.kind != mesh::ElementKind::kTriangle)
    throw InvalidArgument("nu-range: " + t.mesh + " is a " + std::string(mesh::element_kind_name(mesh.kind)) +
                          " mesh; the study runs tet and triangle meshes");
  material::Material m;
  m.plane = t.plane;
  return {calibrate::method_table_name(mesh.kind, m),
          t.mesh + " (plane " + std::string(material::plane_name(t.plane)) + ")", &o.triangle_methods};
}

void log_row(const NuRangeRow& row) {
  char line[240];
  std::snprintf(line, sizeof line, "nu-range: %-28s %-8s %5.3g %% %-10s nu %-5.3g %-21s %s relative L2 %.4g",
                row.mesh.c_str(), row.load.c_str(), 100.0 * row.strain, row.reference.c_str(), row.poisson,
                row.method.c_str(), row.term_law.empty() ? "" : (row.term_law + ",").c_str(), row.relative_l2);
  std::string text = line;
  if (row.control == "displacement") {
    std::snprintf(line, sizeof line, ", force %.4g (m %g, q %g)", row.force_error, row.spring_exponent,
                  row.volume_exponent);
    text += line;
  }
  log(LogLevel::kInfo, text + (row.status == "converged" ? "" : " (" + row.status + ")"));
}

// Every method on one mesh, load, regime and nu: one FEM reference, one spring solve per method.
std::vector<NuRangeRow> run_task(const mesh::Mesh& mesh, const NuRangeOptions& options, const NuRangeTask& task) {
  const Unit u = unit_of(mesh, options, task);
  material::Material material{material::Law::kLinear, 14630.0, task.poisson};
  material.plane = task.plane;
  const std::vector<material::Material> materials{material};
  const std::vector<std::string>& methods = *u.methods;
  CompareOptions o;
  o.load = model::load_kind_from_name(task.load);
  o.strain = task.strain;
  o.reference = material::law_from_name(task.reference);
  std::vector<calibrate::SpringModel> models;
  for (const auto& method : methods)
    models.push_back(calibrate::calibrate(mesh, materials, calibrate::method_from_name(method)));
  std::vector<NuRangeRow> rows;
  for (const auto& method : methods)
    rows.push_back({u.table, u.label, task.load, task.reference, task.strain, task.poisson, method, -1.0, "",
                    "traction", "", 1.0, 1.0, -1.0});
  try {
    const std::vector<Comparison> c = compare_models(mesh, materials, models, o);
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const bool fem_ok = c[m].fem_report.status == solve::SolveStatus::kConverged;
      const bool ok = fem_ok && c[m].spring_report.status == solve::SolveStatus::kConverged;
      rows[m].relative_l2 = ok ? c[m].relative_l2 : -1.0;
      rows[m].status =
          ok ? "converged" : (fem_ok ? "springs: " + c[m].spring_report.message : "FEM: " + c[m].fem_report.message);
    }
  } catch (const SolverFailure& e) {
    for (auto& row : rows) row.status = e.what();
  }
  for (const NuRangeRow& row : rows) log_row(row);
  return rows;
}

// A law regime on one mesh and nu (docs/nu_range.md): per method its model is calibrated, its term law fitted up to
// the regime's strain, and both the Hookean and the fitted model are compared with the law's FEM at that strain under
// displacement control on every load (the FEM solved once per load). A fit that finds no stable law, or an FEM with no
// equilibrium, is recorded in the rows.
std::vector<NuRangeRow> run_law_task(const mesh::Mesh& mesh, const NuRangeOptions& options, const NuRangeTask& task) {
  const Unit u = unit_of(mesh, options, task);
  material::Material material{material::Law::kLinear, 14630.0, task.poisson};
  material.plane = task.plane;
  const material::Law law = material::law_from_name(task.reference);
  TermLawFitOptions fo;
  fo.law = law;
  fo.strain_range = task.strain;
  fo.loads.clear();
  for (const auto& load : options.loads) fo.loads.push_back(model::load_kind_from_name(load));
  fo.refinements = options.fit_refinements;
  // models[2 m] Hookean, models[2 m + 1] fitted (or empty when its fit failed: its rows carry why)
  std::vector<calibrate::CalibratedModel> models;
  std::vector<std::string> fit_failure;
  for (const auto& method : *u.methods) {
    calibrate::ModelOptions mo;
    mo.method = method;
    calibrate::CalibratedModel hookean = calibrate::calibrate_model(mesh, material, mo);
    std::string failure;
    calibrate::CalibratedModel fitted = hookean;
    try {
      fitted = with_fitted_law(hookean, fo);
    } catch (const SolverFailure& e) {
      failure = std::string("fit: ") + e.what();
    }
    models.push_back(std::move(hookean));
    models.push_back(std::move(fitted));
    fit_failure.push_back(failure);
  }
  std::vector<NuRangeRow> rows;
  for (std::size_t l = 0; l < fo.loads.size(); ++l) {
    CompareOptions co;
    co.reference = law;
    co.control = model::LoadControl::kDisplacement;
    co.strain = task.strain;
    std::vector<Reference> refs;
    std::string fem_failure;
    try {
      refs = fem_references(models.front(), {fo.loads[l]}, co);
      if (refs.front().fem.report.status != solve::SolveStatus::kConverged)
        fem_failure = "FEM: " + refs.front().fem.report.message;
    } catch (const SolverFailure& e) {
      fem_failure = std::string("FEM: ") + e.what();
    }
    for (std::size_t m = 0; m < models.size(); ++m) {
      const bool fitted = m % 2 == 1;
      NuRangeRow row{u.table,
                     u.label,
                     options.loads[l],
                     task.reference,
                     task.strain,
                     task.poisson,
                     (*u.methods)[m / 2],
                     -1.0,
                     "",
                     "displacement",
                     fitted ? "fitted" : "hookean",
                     models[m].springs.spring_exponent,
                     models[m].springs.volume_exponent,
                     -1.0};
      if (!fem_failure.empty()) {
        row.status = fem_failure;
      } else if (fitted && !fit_failure[m / 2].empty()) {
        row.status = fit_failure[m / 2];
      } else {
        const Comparison c = compare_to_references(models[m], refs, co).front();
        if (c.spring_report.status == solve::SolveStatus::kConverged) {
          row.relative_l2 = c.relative_l2;
          row.force_error = c.reaction_error;
          row.status = "converged";
        } else {
          row.status = "springs: " + c.spring_report.message;
        }
      }
      log_row(row);
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

// The cases of one table at one nu (mesh, load, regime -> rows), those where no method converged left out (the FEM
// failed, or the load passes a limit point of every spring model: they say nothing about the choice) and counted.
struct Cases {
  std::map<std::string, std::vector<const NuRangeRow*>> rows;
  int left_out = 0;
};

Cases cases_of(const NuRangeReport& r, const std::string& table, double nu, bool small_linear_only) {
  Cases out;
  std::map<std::string, std::vector<const NuRangeRow*>> all;
  for (const auto& row : r.rows)
    if (row.table == table && row.poisson == nu && row.control == "traction" &&
        (!small_linear_only || (row.reference == "linear" && row.strain == r.options.small_strain)))
      all[row.mesh + "|" + row.load + "|" + row.reference + "|" + std::to_string(row.strain)].push_back(&row);
  for (auto& [key, rows] : all) {
    if (std::none_of(rows.begin(), rows.end(), [](const NuRangeRow* x) { return x->relative_l2 >= 0.0; }))
      ++out.left_out;
    else
      out.rows.emplace(key, std::move(rows));
  }
  return out;
}

// Per method, the worst error over the cases; a spring solve that failed where another method converged counts as an
// infinite error.
std::map<std::string, double> worst_of(const Cases& c) {
  std::map<std::string, double> worst;
  for (const auto& [key, rows] : c.rows)
    for (const NuRangeRow* x : rows) {
      double& w = worst[x->method];
      w = std::max(w, x->relative_l2 < 0.0 ? std::numeric_limits<double>::infinity() : x->relative_l2);
    }
  return worst;
}

// The distinct values of `field` over the rows that pass `keep`, in the order the study ran them.
template <typename Field, typename Keep>
std::vector<std::string> distinct(const NuRangeReport& r, Field field, Keep keep) {
  std::vector<std::string> out;
  for (const auto& row : r.rows)
    if (keep(row) && std::find(out.begin(), out.end(), field(row)) == out.end()) out.push_back(field(row));
  return out;
}

std::vector<std::string> tables_of(const NuRangeReport& r) {
  return distinct(
      r, [](const NuRangeRow& x) { return x.table; }, [](const NuRangeRow&) { return true; });
}

// A row's model in a law regime: its method, and "fitted" when its law was fitted.
std::string model_label(const NuRangeRow& row) {
  return row.term_law == "fitted" ? row.method + " fitted" : row.method;
}

// A law-regime row's error: the larger of the displacement's relative L2 and the force error; +inf when it failed.
double law_error(const NuRangeRow& row) {
  return row.relative_l2 < 0.0 ? std::numeric_limits<double>::infinity() : std::max(row.relative_l2, row.force_error);
}

bool in_regime(const NuRangeRow& row, const NuRangeLaw& law) {
  return row.control == "displacement" && row.reference == law.law && row.strain == law.strain;
}

std::string law_label(const NuRangeLaw& law) {
  std::ostringstream s;
  s << law.law << " FEM at " << law.strain * 100.0 << " % strain, displacement control";
  return s.str();
}

// Per table, law regime and nu: the model (method, Hookean or fitted) whose worst error over the meshes and loads
// (the larger of relative L2 and force error) is smallest. Cases where the FEM failed are left out and counted.
std::vector<std::string> recommend_laws(const NuRangeReport& r) {
  std::vector<std::string> out;
  for (const std::string& table : tables_of(r))
    for (const NuRangeLaw& law : r.options.laws)
      for (double nu : r.options.poisson) {
        std::map<std::string, std::vector<const NuRangeRow*>> cases;
        for (const auto& row : r.rows)
          if (row.table == table && row.poisson == nu && in_regime(row, law))
            cases[row.mesh + "|" + row.load].push_back(&row);
        int left_out = 0, counted = 0;
        std::map<std::string, double> worst;
        for (const auto& [key, rows] : cases) {
          if (std::none_of(rows.begin(), rows.end(), [](const NuRangeRow* x) { return x->relative_l2 >= 0.0; })) {
            ++left_out;
            continue;
          }
          ++counted;
          for (const NuRangeRow* x : rows) worst[model_label(*x)] = std::max(worst[model_label(*x)], law_error(*x));
        }
        const auto best = std::min_element(worst.begin(), worst.end(),
                                           [](const auto& a, const auto& b) { return a.second < b.second; });
        if (best == worst.end()) continue;
        char line[320];
        std::snprintf(
            line, sizeof line, "%s, nu = %g, %s: %s, worst of relative L2 and force error %.3f over %d cases%s",
            table.c_str(), nu, law_label(law).c_str(), best->first.c_str(), best->second, counted,
            left_out ? (" (" + std::to_string(left_out) + " where no solve converged left out)").c_str() : "");
        out.push_back(line);
      }
  return out;
}

// Per table and nu: the method whose worst error over the cases (every traction regime) is smallest.
std::vector<std::string> recommend(const NuRangeReport& r) {
  std::vector<std::string> out;
  for (const std::string& table : tables_of(r))
    for (double nu : r.options.poisson) {
      const Cases c = cases_of(r, table, nu, false);
      const std::map<std::string, double> worst = worst_of(c);
      const auto best = std::min_element(worst.begin(), worst.end(),
                                         [](const auto& a, const auto& b) { return a.second < b.second; });
      if (best == worst.end()) continue;
      char line[256];
      std::snprintf(
          line, sizeof line, "%s, nu = %g: %s, worst relative L2 %.3f over %zu cases%s", table.c_str(), nu,
          best->first.c_str(), best->second, c.rows.size(),
          c.left_out ? (" (" + std::to_string(c.left_out) + " where no solve converged left out)").c_str() : "");
      out.push_back(line);
    }
  return out;
}

// The table `--method auto` picks from: the small-strain, linear-FEM regime only (the regime the calibration equates
// stiffness in, and the one `hooke calibrate --certify` measures).
std::vector<calibrate::MeasuredError> method_table(const NuRangeReport& r) {
  std::vector<calibrate::MeasuredError> out;
  for (const std::string& table : tables_of(r))
    for (double nu : r.options.poisson) {
      const Cases c = cases_of(r, table, nu, true);
      const std::map<std::string, double> worst = worst_of(c);
      const auto here = [&](const NuRangeRow& x) { return x.table == table && x.poisson == nu; };
      for (const std::string& method : distinct(
               r, [](const NuRangeRow& x) { return x.method; }, here)) {
        const auto w = worst.find(method);
        if (w != worst.end() && std::isfinite(w->second))
          out.push_back({table, nu, method, w->second, static_cast<int>(c.rows.size())});
      }
    }
  return out;
}

// The meshes (with their plane) in the order they ran, and the methods each ran.
std::vector<std::string> labels_of(const NuRangeReport& r) {
  return distinct(
      r, [](const NuRangeRow& x) { return x.mesh; }, [](const NuRangeRow&) { return true; });
}

std::vector<std::string> methods_of(const NuRangeReport& r, const std::string& label) {
  return distinct(
      r, [](const NuRangeRow& x) { return x.method; }, [&](const NuRangeRow& x) { return x.mesh == label; });
}

std::vector<Figure> figures(const NuRangeReport& r) {
  std::vector<Figure> out;
  const char* styles[] = {"o-", "s-", "^-", "v-", "D-", "x-", "+-"};
  for (const Regime& regime : regimes(r.options)) {
    Figure f;
    f.name = "nu_range_" + regime.reference + "_" + std::to_string(static_cast<int>(regime.strain * 1000 + 0.5));
    f.title = "relative L2 error against nu, " + regime.label() + " (worst over loads)";
    for (const auto& mesh : labels_of(r)) {
      CurvePanel p{mesh, "Poisson's ratio nu", "relative L2 error (worst load)", {}};
      const std::vector<std::string> methods = methods_of(r, mesh);
      for (std::size_t m = 0; m < methods.size(); ++m) {
        Series s{methods[m], styles[m % 7], {}, {}};
        for (double nu : r.options.poisson) {
          double worst = -1.0;
          for (const auto& row : r.rows)
            if (row.mesh == mesh && row.method == methods[m] && row.poisson == nu && row.control == "traction" &&
                row.reference == regime.reference && row.strain == regime.strain && row.relative_l2 >= 0.0)
              worst = std::max(worst, row.relative_l2);
          if (worst < 0.0) continue;
          s.x.push_back(nu);
          s.y.push_back(worst);
        }
        p.series.push_back(s);
      }
      f.panels.emplace_back(p);
    }
    out.push_back(f);
  }
  for (const NuRangeLaw& law : r.options.laws) {
    Figure f;
    f.name = "nu_range_" + law.law + "_" + std::to_string(static_cast<int>(law.strain * 1000 + 0.5)) + "_displacement";
    f.title = "worst of relative L2 and force error against nu, " + law_label(law) + " (worst over loads)";
    for (const auto& mesh : labels_of(r)) {
      CurvePanel p{mesh, "Poisson's ratio nu", "max(relative L2, force error), worst load", {}};
      std::vector<std::string> models;
      for (const auto& row : r.rows)
        if (row.mesh == mesh && in_regime(row, law) &&
            std::find(models.begin(), models.end(), model_label(row)) == models.end())
          models.push_back(model_label(row));
      for (std::size_t m = 0; m < models.size(); ++m) {
        Series s{models[m], std::string(styles[(m / 2) % 7]).substr(0, 1) + (m % 2 ? "-" : "--"), {}, {}};
        for (double nu : r.options.poisson) {
          double worst = -1.0;
          bool failed = false;
          for (const auto& row : r.rows)
            if (row.mesh == mesh && model_label(row) == models[m] && row.poisson == nu && in_regime(row, law)) {
              if (row.relative_l2 < 0.0) failed = true;
              worst = std::max(worst, law_error(row));
            }
          if (worst < 0.0 || failed) continue;
          s.x.push_back(nu);
          s.y.push_back(worst);
        }
        p.series.push_back(s);
      }
      f.panels.emplace_back(p);
    }
    out.push_back(f);
  }
  return out;
}

}  // namespace

std::vector<NuRangeTask> nu_range_tasks(const std::filesystem::path& mesh_dir, const NuRangeOptions& options) {
  for (const auto* list : {&options.methods, &options.triangle_methods})  // refuse unknown names first
    for (const auto& method : *list) calibrate::method_from_name(method);
  for (const auto& load : options.loads) model::load_kind_from_name(load);
  for (const NuRangeLaw& law : options.laws) {
    material::law_from_name(law.law);
    if (!(law.strain > 0.0 && law.strain <= 0.5))
      throw InvalidArgument("nu-range: a law regime's strain must be in (0, 0.5], not " + std::to_string(law.strain));
  }
  if (options.fit_refinements < 0) throw InvalidArgument("nu-range: fit refinements must be >= 0");
  std::vector<material::Plane> planes;
  for (const auto& p : options.planes) planes.push_back(material::plane_from_name(p));
  std::vector<NuRangeTask> out;
  for (const auto& name : options.meshes) {
    const mesh::Mesh mesh = io::read_mesh(mesh_dir / (name + ".msh"));
    std::vector<material::Plane> unit_planes{material::Plane::kStress};
    if (mesh.kind == mesh::ElementKind::kTriangle) unit_planes = planes;
    for (const material::Plane plane : unit_planes) {
      unit_of(mesh, options, {name, plane, "", "", 0.0, 0.0, "traction"});  // refuses meshes of other kinds
      for (const auto& load : options.loads)
        for (const Regime& regime : regimes(options))
          for (double nu : options.poisson)
            out.push_back({name, plane, load, regime.reference, regime.strain, nu, "traction"});
      for (const NuRangeLaw& law : options.laws)
        for (double nu : options.poisson) out.push_back({name, plane, "all", law.law, law.strain, nu, "displacement"});
    }
  }
  return out;
}

std::vector<NuRangeRow> run_nu_range_task(const std::filesystem::path& mesh_dir, const NuRangeOptions& options,
                                          const NuRangeTask& task) {
  const ScopedThreadCount one_thread;  // the same bits on any machine (core/blas_threads.hpp)
  const mesh::Mesh mesh = io::read_mesh(mesh_dir / (task.mesh + ".msh"));
  return task.control == "displacement" ? run_law_task(mesh, options, task) : run_task(mesh, options, task);
}

NuRangeReport nu_range_report(const NuRangeOptions& options, std::vector<NuRangeRow> rows, double seconds) {
  NuRangeReport r;
  r.options = options;
  r.rows = std::move(rows);
  r.recommendations = recommend(r);
  for (std::string& line : recommend_laws(r)) r.recommendations.push_back(std::move(line));
  r.method_table = method_table(r);
  r.figures = figures(r);
  r.seconds = seconds;
  return r;
}

NuRangeReport reproduce_nu_range(const std::filesystem::path& mesh_dir, const NuRangeOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const ScopedThreadCount one_thread;  // the same bits on any machine (core/blas_threads.hpp)
  std::vector<NuRangeRow> rows;
  std::map<std::string, mesh::Mesh> meshes;  // each mesh read once
  for (const NuRangeTask& task : nu_range_tasks(mesh_dir, options)) {
    auto it = meshes.find(task.mesh);
    if (it == meshes.end()) it = meshes.emplace(task.mesh, io::read_mesh(mesh_dir / (task.mesh + ".msh"))).first;
    for (NuRangeRow& row :
         task.control == "displacement" ? run_law_task(it->second, options, task) : run_task(it->second, options, task))
      rows.push_back(std::move(row));
  }
  return nu_range_report(options, std::move(rows),
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

namespace {

nlohmann::json parse_json(const std::string& text, const std::string& what) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw ParseError::at_entry(what, "", e.what());
  }
}

template <typename T>
T entry(const nlohmann::json& j, const char* key, const std::string& what) {
  try {
    return j.at(key).get<T>();
  } catch (const nlohmann::json::exception& e) {
    throw ParseError::at_entry(what, key, e.what());
  }
}

// An entry that older reports and options do not have: `fallback` when absent.
template <typename T>
T optional_entry(const nlohmann::json& j, const char* key, const std::string& what, T fallback) {
  return j.contains(key) ? entry<T>(j, key, what) : fallback;
}

nlohmann::json row_json(const NuRangeRow& row) {
  return {{"table", row.table},
          {"mesh", row.mesh},
          {"load", row.load},
          {"reference", row.reference},
          {"strain", row.strain},
          {"poisson", row.poisson},
          {"method", row.method},
          {"relative_l2", row.relative_l2},
          {"status", row.status},
          {"control", row.control},
          {"term_law", row.term_law},
          {"spring_exponent", row.spring_exponent},
          {"volume_exponent", row.volume_exponent},
          {"force_error", row.force_error}};
}

}  // namespace

std::string nu_range_options_json(const NuRangeOptions& o) {
  nlohmann::json laws = nlohmann::json::array();
  for (const NuRangeLaw& law : o.laws) laws.push_back({{"law", law.law}, {"strain", law.strain}});
  return nlohmann::json{{"poisson", o.poisson},
                        {"methods", o.methods},
                        {"triangle_methods", o.triangle_methods},
                        {"planes", o.planes},
                        {"meshes", o.meshes},
                        {"loads", o.loads},
                        {"small_strain", o.small_strain},
                        {"large_strain", o.large_strain},
                        {"laws", laws},
                        {"fit_refinements", o.fit_refinements}}
      .dump();
}

NuRangeOptions nu_range_options_from_json(const std::string& text) {
  const std::string what = "nu-range options";
  const nlohmann::json j = parse_json(text, what);
  NuRangeOptions o;
  o.poisson = entry<std::vector<double>>(j, "poisson", what);
  o.methods = entry<std::vector<std::string>>(j, "methods", what);
  o.triangle_methods = entry<std::vector<std::string>>(j, "triangle_methods", what);
  o.planes = entry<std::vector<std::string>>(j, "planes", what);
  o.meshes = entry<std::vector<std::string>>(j, "meshes", what);
  o.loads = entry<std::vector<std::string>>(j, "loads", what);
  o.small_strain = entry<double>(j, "small_strain", what);
  o.large_strain = entry<double>(j, "large_strain", what);
  if (j.contains("laws")) {
    o.laws.clear();
    for (const auto& law : entry<nlohmann::json>(j, "laws", what))
      o.laws.push_back({entry<std::string>(law, "law", what), entry<double>(law, "strain", what)});
  }
  o.fit_refinements = optional_entry<int>(j, "fit_refinements", what, o.fit_refinements);
  return o;
}

std::string nu_range_task_json(const NuRangeTask& t) {
  return nlohmann::json{{"mesh", t.mesh},      {"plane", std::string(material::plane_name(t.plane))},
                        {"load", t.load},      {"reference", t.reference},
                        {"strain", t.strain},  {"poisson", t.poisson},
                        {"control", t.control}}
      .dump();
}

NuRangeTask nu_range_task_from_json(const std::string& text) {
  const std::string what = "nu-range task";
  const nlohmann::json j = parse_json(text, what);
  return {entry<std::string>(j, "mesh", what),
          material::plane_from_name(entry<std::string>(j, "plane", what)),
          entry<std::string>(j, "load", what),
          entry<std::string>(j, "reference", what),
          entry<double>(j, "strain", what),
          entry<double>(j, "poisson", what),
          optional_entry<std::string>(j, "control", what, "traction")};
}

std::string nu_range_rows_json(const std::vector<NuRangeRow>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& row : rows) out.push_back(row_json(row));
  return out.dump();
}

std::vector<NuRangeRow> nu_range_rows_from_json(const std::string& text) {
  const std::string what = "nu-range rows";
  const nlohmann::json j = parse_json(text, what);
  if (!j.is_array()) throw ParseError::at_entry(what, "", "expected an array of rows");
  std::vector<NuRangeRow> rows;
  for (const auto& r : j)
    rows.push_back(
        {entry<std::string>(r, "table", what), entry<std::string>(r, "mesh", what), entry<std::string>(r, "load", what),
         entry<std::string>(r, "reference", what), entry<double>(r, "strain", what), entry<double>(r, "poisson", what),
         entry<std::string>(r, "method", what), entry<double>(r, "relative_l2", what),
         entry<std::string>(r, "status", what), optional_entry<std::string>(r, "control", what, "traction"),
         optional_entry<std::string>(r, "term_law", what, ""), optional_entry<double>(r, "spring_exponent", what, 1.0),
         optional_entry<double>(r, "volume_exponent", what, 1.0),
         optional_entry<double>(r, "force_error", what, -1.0)});
  return rows;
}

void write_nu_range_report(const std::filesystem::path& dir, const NuRangeReport& report) {
  create_output_folder(dir);
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& row : report.rows) rows.push_back(row_json(row));
  const nlohmann::json j = {{"study", "spring models against FEM over Poisson's ratio"},
                            {"youngs_modulus_pa", 14630.0},
                            {"rows", rows},
                            {"recommendations", report.recommendations},
                            {"seconds", report.seconds}};
  write_file_atomically(dir / "nu_range.json", [&](std::ostream& o) { o << j.dump(2) << '\n'; });
  write_file_atomically(dir / "method_table.inc",
                        [&](std::ostream& o) { o << calibrate::method_table_source(report.method_table); });
  for (const auto& f : report.figures) write_figure_spec(dir / "figures", f);
  write_file_atomically(dir / "nu_range.md", [&](std::ostream& o) {
    o << "# Spring models against FEM over Poisson's ratio\n\n"
      << "E = 14 630 Pa; relative L2 error |x_spring - x_FEM| / |x_FEM - X| over all nodes (`hooke compare`); "
      << "bottom clamped, uniform traction on the top giving the stated mean linear-FEM strain (law regimes: the top "
      << "moved by strain x height, and the force on it compared too). Every number is in "
      << "nu_range.json; " << report.rows.size() << " comparisons in " << static_cast<int>(report.seconds)
      << " s. A dash is a failed solve (its message is in the JSON).\n\n## What to pick\n\n"
      << "Per table (tets; triangles in plane stress and in plane strain), the method with the smallest worst-case "
         "error over its meshes, the three loads and every traction regime, then per law regime the best model "
         "(`--method auto` picks by the small-strain, "
         "linear-FEM regime alone: method_table.inc):\n\n";
    for (const auto& rec : report.recommendations) o << "- " << rec << "\n";
    for (const auto& f : report.figures) o << "\n![" << f.title << "](figures/" << f.name << ".png)\n";
    for (const auto& mesh : labels_of(report))
      for (const auto& load : report.options.loads)
        for (const Regime& regime : regimes(report.options)) {
          o << "\n## " << mesh << ", " << load << ", " << regime.label() << "\n\n| method |";
          for (double nu : report.options.poisson) o << " " << nu << " |";
          o << "\n|---|";
          for (std::size_t k = 0; k < report.options.poisson.size(); ++k) o << "---|";
          o << "\n";
          for (const auto& method : methods_of(report, mesh)) {
            o << "| " << method << " |";
            for (double nu : report.options.poisson) {
              std::string cell = " ? |";
              for (const auto& row : report.rows)
                if (row.mesh == mesh && row.load == load && row.control == "traction" &&
                    row.reference == regime.reference && row.strain == regime.strain && row.poisson == nu &&
                    row.method == method) {
                  char buf[32];
                  std::snprintf(buf, sizeof buf, " %.3f |", row.relative_l2);
                  cell = row.relative_l2 < 0.0 ? " - |" : buf;
                }
              o << cell;
            }
            o << "\n";
          }
        }
    for (const auto& mesh : labels_of(report))
      for (const NuRangeLaw& law : report.options.laws)
        for (const auto& load : report.options.loads) {
          o << "\n## " << mesh << ", " << load << ", " << law_label(law)
            << "\n\nRelative L2 / force error; a fitted model's exponents (m, q) in brackets.\n\n| model |";
          for (double nu : report.options.poisson) o << " " << nu << " |";
          o << "\n|---|";
          for (std::size_t k = 0; k < report.options.poisson.size(); ++k) o << "---|";
          o << "\n";
          std::vector<std::string> models;
          for (const auto& row : report.rows)
            if (row.mesh == mesh && in_regime(row, law) &&
                std::find(models.begin(), models.end(), model_label(row)) == models.end())
              models.push_back(model_label(row));
          for (const auto& model : models) {
            o << "| " << model << " |";
            for (double nu : report.options.poisson) {
              std::string cell = " ? |";
              for (const auto& row : report.rows)
                if (row.mesh == mesh && row.load == load && in_regime(row, law) && row.poisson == nu &&
                    model_label(row) == model) {
                  char buf[80];
                  if (row.term_law == "fitted")
                    std::snprintf(buf, sizeof buf, " %.3f / %.3f (%g, %g) |", row.relative_l2, row.force_error,
                                  row.spring_exponent, row.volume_exponent);
                  else
                    std::snprintf(buf, sizeof buf, " %.3f / %.3f |", row.relative_l2, row.force_error);
                  cell = row.relative_l2 < 0.0 ? " - |" : buf;
                }
              o << cell;
            }
            o << "\n";
          }
        }
  });
}

}  // namespace hooke::experiments
