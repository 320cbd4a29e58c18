#pragma once
/// The experiments of Lloyd et al. 2007, Sec. 5 and Fig. 1 and 3, as data: each case runs our calibration
/// against the FEM reference and carries the paper's numbers beside ours; figures are specs for matplotlib.
#include <filesystem>
#include <hooke/experiments/figure.hpp>
#include <hooke/experiments/force_displacement.hpp>
#include <string>
#include <vector>

namespace hooke::experiments {

struct Lloyd2007Case {
  std::string id;         ///< e.g. "sec5.1-membrane-stretch"
  std::string section;    ///< "5.1" ... "5.8", or "evidence" for the studies that explain a deviation
  std::string figure;     ///< the paper's figure
  std::string mesh;       ///< mesh description
  std::string method;     ///< calibration method name (or a described variant)
  std::string load;       ///< stretch / compress / shear
  std::string reference;  ///< FEM law
  double strain = 0.0;    ///< target mean strain of the linear FEM
  int nodes = 0, springs = 0, elements = 0;
  std::string status;                                        ///< "converged" or the failing solve's status
  std::string message;                                       ///< solver message when not converged
  double max_error_cm = -1.0, mean_error_cm = -1.0;          ///< ours (negative when not converged)
  double paper_max_cm = -1.0, paper_mean_cm = -1.0;          ///< the paper's (negative where it gives none)
  std::string fit_method;                                    ///< the numerical counterpart run beside it, or ""
  double fit_max_error_cm = -1.0, fit_mean_error_cm = -1.0;  ///< the same case with fit_method
};

/// Fig. 3: error of the Eq. 8 membrane against the FEM for one Poisson's ratio.
struct NuPoint {
  double nu = 0.0;
  std::string load;
  double max_error_cm = -1.0, mean_error_cm = -1.0;          ///< lloyd-equilateral (independent of nu)
  double fit_max_error_cm = -1.0, fit_mean_error_cm = -1.0;  ///< stiffness-fit at this nu
};

struct Lloyd2007Report {
  std::vector<Lloyd2007Case> cases;
  ForceDisplacement triangle, square;  ///< Fig. 1 (a) and (b)
  std::vector<NuPoint> nu_sweep;       ///< Fig. 3
  std::vector<Figure> figures;         ///< drawn by scripts/plot_figures.py into figures/<name>.png
  std::vector<std::string> warnings;   ///< distinct validity warnings of the calibrations (they are expected)
  double seconds = 0.0;                ///< wall time of the experiments
};

/// Runs every experiment. @param mesh_dir  folder with the committed meshes (data/meshes)
Lloyd2007Report reproduce_lloyd2007(const std::filesystem::path& mesh_dir);

/// Writes `dir`/lloyd2007.json (every number), `dir`/lloyd2007.md (tables with the paper beside ours, the
/// figures, and the explanations of the deviations) and the figure specs `dir`/figures/<name>.json, atomically.
void write_lloyd2007_report(const std::filesystem::path& dir, const Lloyd2007Report& report);

}  // namespace hooke::experiments
