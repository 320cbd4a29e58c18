#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/blas_threads.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/log.hpp>
#include <hooke/experiments/compare.hpp>
#include <hooke/experiments/nu_range.hpp>
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
    rows.push_back({u.table, u.label, task.load, task.reference, task.strain, task.poisson, method, -1.0, ""});
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
  for (const NuRangeRow& row : rows) {
    char line[200];
    std::snprintf(line, sizeof line, "nu-range: %-28s %-8s %5.3g %% %-6s nu %-5.3g %-21s relative L2 %.4g",
                  row.mesh.c_str(), row.load.c_str(), 100.0 * row.strain, row.reference.c_str(), row.poisson,
                  row.method.c_str(), row.relative_l2);
    log(LogLevel::kInfo, std::string(line) + (row.status == "converged" ? "" : " (" + row.status + ")"));
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
    if (row.table == table && row.poisson == nu &&
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

// Per table and nu: the method whose worst error over the cases (every regime) is smallest.
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
            if (row.mesh == mesh && row.method == methods[m] && row.poisson == nu &&
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
  return out;
}

}  // namespace

std::vector<NuRangeTask> nu_range_tasks(const std::filesystem::path& mesh_dir, const NuRangeOptions& options) {
  for (const auto* list : {&options.methods, &options.triangle_methods})  // refuse unknown names first
    for (const auto& method : *list) calibrate::method_from_name(method);
  for (const auto& load : options.loads) model::load_kind_from_name(load);
  std::vector<material::Plane> planes;
  for (const auto& p : options.planes) planes.push_back(material::plane_from_name(p));
  std::vector<NuRangeTask> out;
  for (const auto& name : options.meshes) {
    const mesh::Mesh mesh = io::read_mesh(mesh_dir / (name + ".msh"));
    std::vector<material::Plane> unit_planes{material::Plane::kStress};
    if (mesh.kind == mesh::ElementKind::kTriangle) unit_planes = planes;
    for (const material::Plane plane : unit_planes) {
      unit_of(mesh, options, {name, plane, "", "", 0.0, 0.0});  // refuses meshes of other kinds
      for (const auto& load : options.loads)
        for (const Regime& regime : regimes(options))
          for (double nu : options.poisson) out.push_back({name, plane, load, regime.reference, regime.strain, nu});
    }
  }
  return out;
}

std::vector<NuRangeRow> run_nu_range_task(const std::filesystem::path& mesh_dir, const NuRangeOptions& options,
                                          const NuRangeTask& task) {
  const ScopedBlasThreads one_thread;  // the same bits on any machine (core/blas_threads.hpp)
  return run_task(io::read_mesh(mesh_dir / (task.mesh + ".msh")), options, task);
}

NuRangeReport nu_range_report(const NuRangeOptions& options, std::vector<NuRangeRow> rows, double seconds) {
  NuRangeReport r;
  r.options = options;
  r.rows = std::move(rows);
  r.recommendations = recommend(r);
  r.method_table = method_table(r);
  r.figures = figures(r);
  r.seconds = seconds;
  return r;
}

NuRangeReport reproduce_nu_range(const std::filesystem::path& mesh_dir, const NuRangeOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const ScopedBlasThreads one_thread;  // the same bits on any machine (core/blas_threads.hpp)
  std::vector<NuRangeRow> rows;
  std::map<std::string, mesh::Mesh> meshes;  // each mesh read once
  for (const NuRangeTask& task : nu_range_tasks(mesh_dir, options)) {
    auto it = meshes.find(task.mesh);
    if (it == meshes.end()) it = meshes.emplace(task.mesh, io::read_mesh(mesh_dir / (task.mesh + ".msh"))).first;
    for (NuRangeRow& row : run_task(it->second, options, task)) rows.push_back(std::move(row));
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

nlohmann::json row_json(const NuRangeRow& row) {
  return {{"table", row.table},   {"mesh", row.mesh},       {"load", row.load},     {"reference", row.reference},
          {"strain", row.strain}, {"poisson", row.poisson}, {"method", row.method}, {"relative_l2", row.relative_l2},
          {"status", row.status}};
}

}  // namespace

std::string nu_range_options_json(const NuRangeOptions& o) {
  return nlohmann::json{{"poisson", o.poisson},
                        {"methods", o.methods},
                        {"triangle_methods", o.triangle_methods},
                        {"planes", o.planes},
                        {"meshes", o.meshes},
                        {"loads", o.loads},
                        {"small_strain", o.small_strain},
                        {"large_strain", o.large_strain}}
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
  return o;
}

std::string nu_range_task_json(const NuRangeTask& t) {
  return nlohmann::json{{"mesh", t.mesh},     {"plane", std::string(material::plane_name(t.plane))},
                        {"load", t.load},     {"reference", t.reference},
                        {"strain", t.strain}, {"poisson", t.poisson}}
      .dump();
}

NuRangeTask nu_range_task_from_json(const std::string& text) {
  const std::string what = "nu-range task";
  const nlohmann::json j = parse_json(text, what);
  return {entry<std::string>(j, "mesh", what), material::plane_from_name(entry<std::string>(j, "plane", what)),
          entry<std::string>(j, "load", what), entry<std::string>(j, "reference", what),
          entry<double>(j, "strain", what),    entry<double>(j, "poisson", what)};
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
    rows.push_back({entry<std::string>(r, "table", what), entry<std::string>(r, "mesh", what),
                    entry<std::string>(r, "load", what), entry<std::string>(r, "reference", what),
                    entry<double>(r, "strain", what), entry<double>(r, "poisson", what),
                    entry<std::string>(r, "method", what), entry<double>(r, "relative_l2", what),
                    entry<std::string>(r, "status", what)});
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
      << "bottom clamped, uniform traction on the top giving the stated mean linear-FEM strain. Every number is in "
      << "nu_range.json; " << report.rows.size() << " comparisons in " << static_cast<int>(report.seconds)
      << " s. A dash is a failed solve (its message is in the JSON).\n\n## What to pick\n\n"
      << "Per table (tets; triangles in plane stress and in plane strain), the method with the smallest worst-case "
         "error over its meshes, the three loads and every regime (`--method auto` picks by the small-strain, "
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
                if (row.mesh == mesh && row.load == load && row.reference == regime.reference &&
                    row.strain == regime.strain && row.poisson == nu && row.method == method) {
                  char buf[32];
                  std::snprintf(buf, sizeof buf, " %.3f |", row.relative_l2);
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
