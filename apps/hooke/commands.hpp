#pragma once
// Sub-commands of the hooke tool. Each registers its options on `app` and returns the action to run.
#include <CLI/CLI.hpp>
#include <cmath>
#include <functional>
#include <hooke/calibrate/calibrated_model.hpp>
#include <hooke/core/settings.hpp>
#include <hooke/experiments/calibration.hpp>
#include <hooke/solve/dynamics_setup.hpp>
#include <hooke/solve/simulator.hpp>
#include <string>
#include <utility>
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

/// Settings given on the command line, in the order given: (name, text), for settings::apply.
using GivenSettings = std::vector<std::pair<std::string, std::string>>;

/// Registers --NAME for every row of `rows` on `cmd` (a flag for a flag row), its help, unit, range and default
/// generated from the row (settings::Description); what is given lands in `given`, to be checked and applied by the
/// library (settings::apply). `group` titles them in --help (empty: the command's own options).
void add_settings(CLI::App* cmd, const std::vector<settings::Description>& rows, GivenSettings& given,
                  const std::string& group = "");

/// Where a command's model comes from: a model file (--model), or a mesh calibrated from E, nu with the calibration
/// settings (experiments::calibration_settings()) given on the command line.
struct ModelSource {
  std::string mesh_path, unit = "m", model_path, law = "linear", plane = "stress";
  double young = std::nan(""), poisson = std::nan(""), thickness = 1e-3;  ///< NaN: not given
  GivenSettings given;                 ///< the calibration settings given (--method, --density, --size, ...)
  std::vector<std::string> materials;  ///< --material REGION=E,NU, as given
};

/// Registers [MESH], --model, --young, --poisson, --material, --unit, --thickness, --plane and every calibration
/// setting of `command` (settings::Command) on `cmd`, bound to `in`.
void add_model_source_options(CLI::App* cmd, ModelSource& in, unsigned command);
/// The calibration settings `in` gives, lengths converted from the mesh unit to metres.
/// @throws InvalidArgument for a malformed or out-of-range value, naming the option
experiments::CalibrationSettings calibration_settings(const ModelSource& in);
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
