#pragma once
/// The experiments of Lloyd et al. 2007, Sec. 5, as data: each case runs our calibration against the FEM
/// reference and carries the paper's numbers beside ours.
#include <filesystem>
#include <string>
#include <vector>

namespace hooke::experiments {

struct Lloyd2007Case {
  std::string id;         ///< e.g. "sec5.1-membrane-stretch"
  std::string figure;     ///< the paper's figure
  std::string mesh;       ///< mesh description with counts
  std::string method;     ///< calibration method name
  std::string load;       ///< stretch / compress / shear
  std::string reference;  ///< FEM law
  double strain = 0.0;    ///< target mean strain of the linear FEM
  int nodes = 0, springs = 0, elements = 0;
  std::string status;                                        ///< "converged" or the solver's status when it is not
  std::string message;                                       ///< solver message when not converged
  double max_error_cm = -1.0, mean_error_cm = -1.0;          ///< ours (negative when not converged)
  double paper_max_cm = -1.0, paper_mean_cm = -1.0;          ///< the paper's (negative where it gives none)
  double fit_max_error_cm = -1.0, fit_mean_error_cm = -1.0;  ///< the same case with stiffness-fit
};

/// Runs every case that the library supports so far. @param mesh_dir  folder with the committed meshes
std::vector<Lloyd2007Case> reproduce_lloyd2007(const std::filesystem::path& mesh_dir);

/// Writes `dir`/lloyd2007.json (every number) and `dir`/lloyd2007.md (tables, paper beside ours), atomically.
void write_lloyd2007_report(const std::filesystem::path& dir, const std::vector<Lloyd2007Case>& cases);

}  // namespace hooke::experiments
