#include <algorithm>
#include <chrono>
#include <cstdio>
#include <hooke/core/atomic_file.hpp>
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

// Every method on one mesh, load, regime and nu: one FEM reference, one spring solve per method.
std::vector<NuRangeRow> run_rows(const mesh::Mesh& mesh, const std::string& mesh_name, const std::string& load,
                                 const Regime& regime, double nu, const std::vector<std::string>& methods) {
  const std::vector<material::Material> materials{material::Material{material::Law::kLinear, 14630.0, nu}};
  CompareOptions o;
  o.load = load_kind_from_name(load);
  o.strain = regime.strain;
  o.reference = material::law_from_name(regime.reference);
  std::vector<calibrate::SpringModel> models;
  for (const auto& method : methods)
    models.push_back(calibrate::calibrate(mesh, materials, calibrate::method_from_name(method)));
  std::vector<NuRangeRow> rows;
  for (const auto& method : methods)
    rows.push_back({mesh_name, load, regime.reference, regime.strain, nu, method, -1.0, ""});
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
  return rows;
}

// Per nu: the method whose worst error over the cases is smallest. A case where the FEM failed has no reference, and
// a case where every method's springs failed (the load passes a limit point of every spring model) says nothing
// about the choice: both are left out and counted. A spring solve that failed where another method converged
// counts as an infinite error.
std::vector<std::string> recommend(const NuRangeReport& r) {
  std::vector<std::string> out;
  for (double nu : r.options.poisson) {
    std::map<std::string, std::vector<const NuRangeRow*>> cases;  // mesh, load, regime -> rows
    for (const auto& row : r.rows)
      if (row.poisson == nu)
        cases[row.mesh + "|" + row.load + "|" + row.reference + "|" + std::to_string(row.strain)].push_back(&row);
    std::map<std::string, double> worst;
    int left_out = 0;
    for (const auto& [key, rows] : cases) {
      if (std::none_of(rows.begin(), rows.end(), [](const NuRangeRow* x) { return x->relative_l2 >= 0.0; })) {
        ++left_out;
        continue;
      }
      for (const NuRangeRow* x : rows) {
        double& w = worst[x->method];
        w = std::max(w, x->relative_l2 < 0.0 ? std::numeric_limits<double>::infinity() : x->relative_l2);
      }
    }
    const auto best =
        std::min_element(worst.begin(), worst.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    if (best == worst.end()) continue;
    char line[256];
    std::snprintf(line, sizeof line, "nu = %g: %s, worst relative L2 %.3f over %zu cases%s", nu, best->first.c_str(),
                  best->second, cases.size() - static_cast<std::size_t>(left_out),
                  left_out ? (" (" + std::to_string(left_out) + " where no solve converged left out)").c_str() : "");
    out.push_back(line);
  }
  return out;
}

std::vector<Figure> figures(const NuRangeReport& r) {
  std::vector<Figure> out;
  const char* styles[] = {"o-", "s-", "^-", "v-", "D-", "x-", "+-"};
  for (const Regime& regime : regimes(r.options)) {
    Figure f;
    f.name = "nu_range_" + regime.reference + "_" + std::to_string(static_cast<int>(regime.strain * 1000 + 0.5));
    f.title = "relative L2 error against nu, " + regime.label() + " (worst over loads)";
    for (const auto& mesh : r.options.meshes) {
      CurvePanel p{mesh, "Poisson's ratio nu", "relative L2 error (worst load)", {}};
      for (std::size_t m = 0; m < r.options.methods.size(); ++m) {
        Series s{r.options.methods[m], styles[m % 7], {}, {}};
        for (double nu : r.options.poisson) {
          double worst = -1.0;
          for (const auto& row : r.rows)
            if (row.mesh == mesh && row.method == r.options.methods[m] && row.poisson == nu &&
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

NuRangeReport reproduce_nu_range(const std::filesystem::path& mesh_dir, const NuRangeOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  NuRangeReport r;
  r.options = options;
  for (const auto& method : options.methods) calibrate::method_from_name(method);  // refuse unknown names first
  for (const auto& load : options.loads) load_kind_from_name(load);
  for (const auto& name : options.meshes) {
    const mesh::Mesh mesh = io::read_mesh(mesh_dir / (name + ".msh"));
    for (const auto& load : options.loads)
      for (const Regime& regime : regimes(options))
        for (double nu : options.poisson)
          for (const NuRangeRow& row : run_rows(mesh, name, load, regime, nu, options.methods)) {
            r.rows.push_back(row);
            char line[160];
            std::snprintf(line, sizeof line, "nu-range: %-13s %-8s %5.3g %% %-6s nu %-5.3g %-21s relative L2 %.4g",
                          name.c_str(), load.c_str(), 100.0 * regime.strain, regime.reference.c_str(), nu,
                          row.method.c_str(), row.relative_l2);
            log(LogLevel::kInfo, std::string(line) + (row.status == "converged" ? "" : " (" + row.status + ")"));
          }
  }
  r.recommendations = recommend(r);
  r.figures = figures(r);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

void write_nu_range_report(const std::filesystem::path& dir, const NuRangeReport& report) {
  create_output_folder(dir);
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& row : report.rows)
    rows.push_back({{"mesh", row.mesh},
                    {"load", row.load},
                    {"reference", row.reference},
                    {"strain", row.strain},
                    {"poisson", row.poisson},
                    {"method", row.method},
                    {"relative_l2", row.relative_l2},
                    {"status", row.status}});
  const nlohmann::json j = {{"study", "spring models against FEM over Poisson's ratio (issue 15)"},
                            {"youngs_modulus_pa", 14630.0},
                            {"rows", rows},
                            {"recommendations", report.recommendations},
                            {"seconds", report.seconds}};
  write_file_atomically(dir / "nu_range.json", [&](std::ostream& o) { o << j.dump(2) << '\n'; });
  for (const auto& f : report.figures) write_figure_spec(dir / "figures", f);
  write_file_atomically(dir / "nu_range.md", [&](std::ostream& o) {
    o << "# Spring models against FEM over Poisson's ratio\n\n"
      << "E = 14 630 Pa; relative L2 error |x_spring - x_FEM| / |x_FEM - X| over all nodes (`hooke compare`); "
      << "bottom clamped, uniform traction on the top giving the stated mean linear-FEM strain. Every number is in "
      << "nu_range.json; " << report.rows.size() << " comparisons in " << static_cast<int>(report.seconds)
      << " s. A dash is a failed solve (its message is in the JSON).\n\n## What to pick\n\n"
      << "The method with the smallest worst-case error over both meshes, the three loads and every regime:\n\n";
    for (const auto& rec : report.recommendations) o << "- " << rec << "\n";
    for (const auto& f : report.figures) o << "\n![" << f.title << "](figures/" << f.name << ".png)\n";
    for (const auto& mesh : report.options.meshes)
      for (const auto& load : report.options.loads)
        for (const Regime& regime : regimes(report.options)) {
          o << "\n## " << mesh << ", " << load << ", " << regime.label() << "\n\n| method |";
          for (double nu : report.options.poisson) o << " " << nu << " |";
          o << "\n|---|";
          for (std::size_t k = 0; k < report.options.poisson.size(); ++k) o << "---|";
          o << "\n";
          for (const auto& method : report.options.methods) {
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
