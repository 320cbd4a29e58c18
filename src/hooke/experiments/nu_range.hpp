#pragma once
/// The study beyond the papers: every calibration method against the FEM over Poisson's ratios from 0 to 0.49,
/// stretch / compress / shear, in the linear regime and at 12 % strain (against linear and StVK FEM), on the cylinder
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
};

/// One comparison: a method at one nu on one mesh, load and regime.
struct NuRangeRow {
  std::string table;  ///< calibrate::method_table_name of the mesh and material: "tet", "triangle plane-stress", ...
  std::string mesh, load;
  std::string reference;  ///< "linear" or "stvk"
  double strain = 0.0;    ///< mean linear-FEM strain of the load
  double poisson = 0.0;
  std::string method;
  double relative_l2 = -1.0;  ///< |x_spring - x_fem| / |x_fem - X| over all nodes; -1 when a solve failed
  std::string status;         ///< "converged" or the failing solve's status and message
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

/// The study runs the BLAS on one thread (ScopedBlasThreads), so that its numbers are the same bits on any machine and
/// in any process: the serial run and hooke.batch's Dask workers write the same report.
///
/// One independent piece of the study: every method of a mesh's table on one mesh, plane, load, regime and nu (one
/// FEM reference shared by the methods). The study is the concatenation of its tasks' rows in nu_range_tasks' order,
/// so tasks may run anywhere (hooke.batch on Dask) and give the serial study's report.
struct NuRangeTask {
  std::string mesh;                                  ///< committed mesh name (data/meshes/<mesh>.msh)
  material::Plane plane = material::Plane::kStress;  ///< the 2D reduction (triangle meshes; tets: kStress)
  std::string load;                                  ///< "stretch", "compress" or "shear"
  std::string reference;                             ///< "linear" or "stvk"
  double strain = 0.0;                               ///< mean linear-FEM strain of the load
  double poisson = 0.0;                              ///< nu
};

/// The study's tasks in the order the serial study runs them (meshes, planes, loads, regimes, nu).
/// @throws IoError when a mesh is missing; InvalidArgument for an unknown method, load or plane, or a mesh that is
///         neither tets nor triangles
std::vector<NuRangeTask> nu_range_tasks(const std::filesystem::path& mesh_dir, const NuRangeOptions& options = {});

/// The rows of one task (one per method of the mesh's table, in options' order), each logged at LogLevel::kInfo.
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
