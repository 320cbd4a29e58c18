#pragma once
/// The study beyond the papers: every calibration method against the FEM over Poisson's ratios from 0 to 0.49,
/// stretch / compress / shear, in the linear regime and at 12 % strain (against linear and StVK FEM) under traction
/// control, and in the law regimes (Neo-Hookean FEM at 20 %, StVK at 12 %) under displacement control with Hookean
/// terms and with each model's term law fitted up to that strain (experiments::fit_term_law), on the cylinder
/// with a hole and the cone (tet methods) and a triangulated rectangle in plane stress and plane strain (triangle
/// methods), with a figure of error against nu, a recommendation per nu and the table `--method auto` picks from
/// (calibrate::choose_method).
#include <filesystem>
#include <hooke/calibrate/method_choice.hpp>
#include <hooke/experiments/figure.hpp>
#include <hooke/material/material.hpp>
#include <string>
#include <vector>

namespace hooke::experiments {

/// A law regime of the study: every method against the FEM of `law` under displacement control at `strain` (stretch,
/// compression and shear: the top moved by strain x height), once with Hookean terms and once with its term law fitted
/// up to `strain` (docs/methods/large_strain.md). Relative L2 and the force on the top are both recorded.
struct NuRangeLaw {
  std::string law;      ///< the FEM law: "neohookean", "stvk" or "linear" (material::law_from_name)
  double strain = 0.2;  ///< the measured strain and the fitted range, in (0, 0.5]
};

struct NuRangeOptions {
  std::vector<double> poisson = {0.0, 0.1, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.49};  ///< nu values
  std::vector<std::string> methods = {"lloyd-tet", "lloyd-tet-volume", "stiffness-fit", "stiffness-fit-volume",
                                      "any-nu-tet"};  ///< methods for tet meshes
  std::vector<std::string> triangle_methods = {"lloyd-triangle", "any-nu-triangle", "stiffness-fit",
                                               "vangelder"};  ///< methods for triangle meshes
  std::vector<std::string> planes = {"stress", "strain"};     ///< the 2D reductions triangle meshes are run in
  /// committed meshes (data/meshes/<name>.msh), tets or triangles
  std::vector<std::string> meshes = {"cylinder_hole", "cone", "rectangle_tri"};
  std::vector<std::string> loads = {"stretch", "compress", "shear"};
  double small_strain = 0.001;  ///< the linear regime, default 0.1 %
  double large_strain = 0.12;   ///< the papers' large deformation, default 12 % (0: skip both large regimes)
  /// the law regimes (empty: none), each one task per mesh, plane and nu that fits every method's law once
  std::vector<NuRangeLaw> laws = {{"neohookean", 0.2}, {"stvk", 0.12}};
  int fit_refinements = 3;  ///< the law fit's pattern-search steps (TermLawFitOptions::refinements), >= 0
};

/// One comparison: a method at one nu on one mesh, load and regime.
struct NuRangeRow {
  std::string table;  ///< calibrate::method_table_name of the mesh and material: "tet", "triangle plane-stress", ...
  std::string mesh, load;
  std::string reference;  ///< the FEM law: "linear", "stvk" or "neohookean"
  double strain = 0.0;  ///< traction control: mean linear-FEM strain of the load; displacement control: the top's move
  double poisson = 0.0;
  std::string method;
  double relative_l2 = -1.0;         ///< |x_spring - x_fem| / |x_fem - X| over all nodes; -1 when a solve failed
  std::string status;                ///< "converged" or the failing solve's status and message
  std::string control = "traction";  ///< "traction", or "displacement" in the law regimes
  /// the law regimes: "hookean" (m = q = 1) or "fitted" (the exponents below fitted up to `strain`); else empty
  std::string term_law;
  double spring_exponent = 1.0, volume_exponent = 1.0;  ///< the model's Seth-Hill exponents (m, q)
  double force_error = -1.0;  ///< displacement control: |R_model - R_FEM| / |R_FEM| of the top's force; else -1
};

struct NuRangeReport {
  NuRangeOptions options;
  std::vector<NuRangeRow> rows;
  /// Per table and nu, the method with the smallest worst-case error over meshes, loads and regimes, with that error.
  std::vector<std::string> recommendations;
  /// Per table, nu and method, the worst error at small strain against the linear FEM over the table's meshes and
  /// loads (what `--method auto` picks from; a method that failed a case where another converged is left out).
  std::vector<calibrate::MeasuredError> method_table;
  std::vector<Figure> figures;  ///< error against nu per method, one figure per regime
  double seconds = 0.0;
};

/// The study runs the BLAS and OpenMP on one thread (ScopedThreadCount), so that its numbers are the same bits on any
/// machine and in any process: the serial run and hooke.batch's Dask workers write the same report.
///
/// One independent piece of the study: every method of a mesh's table on one mesh, plane, load, regime and nu (one
/// FEM reference shared by the methods). The study is the concatenation of its tasks' rows in nu_range_tasks' order,
/// so tasks may run anywhere (hooke.batch on Dask) and give the serial study's report.
struct NuRangeTask {
  std::string mesh;                                  ///< committed mesh name (data/meshes/<mesh>.msh)
  material::Plane plane = material::Plane::kStress;  ///< the 2D reduction (triangle meshes; tets: kStress)
  /// "stretch", "compress" or "shear"; "all" in a law regime, whose fit measures every load of the options together
  std::string load;
  std::string reference;             ///< the FEM law: "linear", "stvk" (traction) or a law regime's law
  double strain = 0.0;               ///< mean linear-FEM strain of the load, or the law regime's strain
  double poisson = 0.0;              ///< nu
  std::string control = "traction";  ///< "traction", or "displacement" for a law regime
};

/// The study's tasks in the order the serial study runs them (meshes, planes, loads, regimes, nu; then per mesh and
/// plane the law regimes, nu).
/// @throws IoError when a mesh is missing; InvalidArgument for an unknown method, load or plane, or a mesh that is
///         neither tets nor triangles
std::vector<NuRangeTask> nu_range_tasks(const std::filesystem::path& mesh_dir, const NuRangeOptions& options = {});

/// The rows of one task (one per method of the mesh's table, in options' order; in a law regime, per load and method a
/// Hookean row and a fitted row), each logged at LogLevel::kInfo.
/// A solve that fails is recorded in its row (relative_l2 -1 and the message), not thrown.
/// @throws IoError when the mesh is missing
std::vector<NuRangeRow> run_nu_range_task(const std::filesystem::path& mesh_dir, const NuRangeOptions& options,
                                          const NuRangeTask& task);

/// The report of a study from its rows (the concatenation of the tasks' rows in order): recommendations, the method
/// table and the figures. `seconds`: the study's wall time.
NuRangeReport nu_range_report(const NuRangeOptions& options, std::vector<NuRangeRow> rows, double seconds);

/// Runs the study (E = 14 630 Pa; experiments::compare for every row): every task of nu_range_tasks in order, then
/// nu_range_report. About 20 minutes on one core with the defaults. @param mesh_dir  the committed meshes
/// @throws IoError when a mesh is missing; InvalidArgument for an unknown method or load
NuRangeReport reproduce_nu_range(const std::filesystem::path& mesh_dir, const NuRangeOptions& options = {});

/// JSON forms of the options, a task and rows (numbers round-trip exactly), for studies run as separate processes.
/// @throws ParseError (from the _from_json functions) naming the missing or mistyped entry
std::string nu_range_options_json(const NuRangeOptions& options);
NuRangeOptions nu_range_options_from_json(const std::string& json);
std::string nu_range_task_json(const NuRangeTask& task);
NuRangeTask nu_range_task_from_json(const std::string& json);
std::string nu_range_rows_json(const std::vector<NuRangeRow>& rows);
std::vector<NuRangeRow> nu_range_rows_from_json(const std::string& json);

/// Writes `dir`/nu_range.json (every row), `dir`/nu_range.md (one table per mesh, plane, load and regime: methods x
/// nu; the recommendations), `dir`/method_table.inc (the method table as src/hooke/calibrate/method_table.inc holds it)
/// and the figure specs under `dir`/figures/.
void write_nu_range_report(const std::filesystem::path& dir, const NuRangeReport& report);

}  // namespace hooke::experiments
