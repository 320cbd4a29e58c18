#pragma once
// Sub-commands of the hooke tool. Each registers its options on `app` and returns the action to run.
#include <CLI/CLI.hpp>
#include <cmath>
#include <functional>
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/calibrate/surface_model.hpp>
#include <hooke/mesh/tetrahedralize.hpp>
#include <hooke/solve/dynamics_setup.hpp>
#include <hooke/solve/simulator.hpp>
#include <string>
#include <vector>

namespace hooke::cli {

using Action = std::function<int()>;

/// What every model-building command reads: the mesh file, its length unit, E, nu and the 2D thickness.
struct ModelInput {
  std::string mesh_path, unit = "m";
  double young = 0.0, poisson = 0.0, thickness = 1e-3;
};

/// Registers MESH, --young, --poisson, --unit and --thickness on `cmd`, bound to `in`.
void add_model_input_options(CLI::App* cmd, ModelInput& in);

/// The surface model's options (`--method surface`): scheme, readings of the paper's equations, centre.
struct SurfaceInput {
  std::string scheme = "D", anchor_law, volume_force = "nodal";
  std::vector<double> centre;  ///< x,y,z in m, or empty for the volume centroid
};
/// Registers --scheme, --anchor-law, --volume-force and --centre on `cmd`.
void add_surface_options(CLI::App* cmd, SurfaceInput& in);
/// The library options they select (density, mass and thickness left at their defaults).
/// @throws InvalidArgument for an unknown name or a centre without three components
calibrate::SurfaceOptions surface_options(const SurfaceInput& in);

/// How a closed surface is made into tets (mesh::tetrahedralize): lengths in the mesh file's unit.
struct TetrahedralizeInput {
  double size = 0.0, max_volume = 0.0;  ///< --size (unit), --max-volume (unit^3); 0: not given
  std::string surface_mesh = "keep";
  std::string mesher = "netgen";
  mesh::TetrahedralizeOptions options;  ///< the numbers bound directly (quality, fineness, grading, steps)
};
/// Registers --mesher, --size, --max-volume, --quality, --surface-mesh, --fineness, --grading and --optimisation-steps.
void add_tetrahedralize_options(CLI::App* cmd, TetrahedralizeInput& in);
/// The library options `in` selects, lengths converted to metres with `metres_per_unit`.
/// @throws InvalidArgument for --size with --max-volume (mesh::set_mesh_size), or an unknown --surface-mesh or --mesher
mesh::TetrahedralizeOptions tetrahedralize_options(const TetrahedralizeInput& in, double metres_per_unit);

/// Where a command's model comes from: a model file (--model), or a mesh calibrated by --method from E, nu.
struct ModelSource {
  std::string mesh_path, unit = "m", model_path, method = "auto", law = "linear", plane = "stress";
  double young = std::nan(""), poisson = std::nan(""), thickness = 1e-3, density = 1000.0;  ///< NaN: not given
  double spring_exponent = 1.0, volume_exponent = 1.0;  ///< the term law (calibrate::ModelOptions)
  SurfaceInput surface;
  TetrahedralizeInput tetrahedralize;  ///< a closed surface given to a tet method
};
/// Registers --spring-exponent and --volume-exponent (the models' term law, calibrate::ModelOptions) on `cmd`.
void add_term_law_options(CLI::App* cmd, double& spring_exponent, double& volume_exponent);

/// Registers [MESH], --model, --young, --poisson, --method, --unit, --thickness, --density, --plane, the
/// surface model's options and the tetrahedralization options on `cmd`, bound to `in`.
void add_model_source_options(CLI::App* cmd, ModelSource& in);
/// The model `in` names: read from --model (checked against MESH when one is given too; a MESH ending in .json is
/// read as --model), or calibrated on MESH by the library's model factory.
/// @throws InvalidArgument when neither or a conflicting combination is given
calibrate::CalibratedModel load_model(const ModelSource& in);

/// The time integrator and its options as given on the command line (solve::simulator_fields(), in its order;
/// empty: not given).
struct IntegratorInput {
  std::vector<std::string> values;
};
/// Registers every solve::simulator_fields() entry as --NAME on `cmd` (--integrator, --qn-iterations,
/// --cg-tolerance, ...), the defaults shown being `options`' values; the text given lands in `in`.
void add_integrator_options(CLI::App* cmd, IntegratorInput& in, const solve::SimulatorOptions& options);
/// Sets the fields given in `in` on `options`. @throws InvalidArgument for an unknown name or a malformed number
void apply_integrator_options(const IntegratorInput& in, solve::SimulatorOptions& options);

/// Registers every solve::dynamics_fields() entry as --NAME on `cmd` (--dt, --gravity, --damping-mass, ...), bound
/// to `setup` (whose values are the defaults shown), as `simulate` and `view` take them.
void add_dynamics_options(CLI::App* cmd, solve::DynamicsSetup& setup);

/// Every number given to an option of type FLOAT of the parsed (sub)commands is finite: "nan", "inf" and overflowing
/// values are refused before anything runs (an unchecked NaN slips through comparisons).
/// @throws InvalidArgument naming the option and the value
void require_finite_numbers(const CLI::App& app);

/// Parses argv into `app`, checks its numbers (require_finite_numbers) and runs `action`, mapping the outcome to the
/// exit code every hooke program uses: 0 success (and --help), 2 bad input or a parse error, 3 solver failure, 4
/// internal error; messages go to stderr prefixed with `program`.
int parse_and_run(CLI::App& app, int argc, char** argv, const char* program, const std::function<int()>& action);

/// `hooke fem`: linear or nonlinear FEM reference solve of a load case.
Action add_fem_command(CLI::App& app);
/// `hooke compare`: a calibrated spring model against the FEM reference.
Action add_compare_command(CLI::App& app);
/// `hooke reproduce lloyd2007`: the paper's Sec. 5 experiments and a report.
Action add_reproduce_command(CLI::App& app);
/// `hooke simulate`: dynamics with a ParaView time series and a timing report.
Action add_simulate_command(CLI::App& app);
/// `hooke bench`: the dynamics benchmark table.
Action add_bench_command(CLI::App& app);
/// `hooke calibrate`: writes a calibrated model (.json, .vtu, .csv), optionally certified against FEM.
Action add_calibrate_command(CLI::App& app);
/// `hooke identify`: a spring model identified from reference deformations (Lloyd Eq. 1-2).
Action add_identify_command(CLI::App& app);
/// `hooke batch`: a study table's jobs on Dask distributed (hooke.batch).
Action add_batch_command(CLI::App& app);
/// `hooke mesh info|convert`: inspect and convert meshes.
Action add_mesh_command(CLI::App& app);

}  // namespace hooke::cli
