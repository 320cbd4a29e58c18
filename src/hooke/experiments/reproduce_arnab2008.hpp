#pragma once
/// The experiments of Arnab & Raja ("A Deformable Surface Model for Soft Volume Simulation") as data: each
/// table is a function that builds its meshes, runs its cases and returns our numbers beside the paper's.
#include <filesystem>
#include <string>
#include <vector>

namespace hooke::experiments {

/// Table 1: Young's modulus re-extracted from a cube surface model under a pressure on its top face.
struct YoungsModulusRow {
  int nodes = 0;                         ///< surface nodes of the cube (602, 1352, 2402)
  double youngs_modulus = 0.0;           ///< E given to the model, Pa
  double extracted_d = 0.0;              ///< E re-extracted from scheme D, Pa
  double extracted_c = 0.0;              ///< the same with scheme C (single stiffness dimension), Pa
  double extracted_d_no_membrane = 0.0;  ///< scheme D without membrane springs (t = 0), Pa
  double deviation_percent = 0.0;        ///< 100 (extracted_d / E - 1)
  double paper = 0.0;                    ///< the paper's value, Pa
  int newton_iterations = 0;             ///< of scheme D's static solve
};

/// Table 2: steps per second of the surface model (scheme D) and of the volumetric spring model of the same
/// object (lloyd-tet springs on its tetrahedralisation), symplectic Euler at the same dt.
struct FrameRateRow {
  std::string model;      ///< "cube 602", ...
  int surface_nodes = 0;  ///< nodes of the surface model
  int volume_nodes = 0;   ///< nodes of the volumetric model
  double dt = 0.0;        ///< the common time step, s (0.9 x the smaller stability limit)
  double surface_steps_per_second = 0.0, volume_steps_per_second = 0.0;  ///< medians
  double paper_surface_fps = 0.0, paper_volume_fps = 0.0;                ///< the paper's frame rates
};

struct Arnab2008Report {
  double poisson_ratio = 0.3;             ///< nu used throughout (the paper gives none)
  double cube_size = 0.1;                 ///< cube edge, m
  double strain_load = 0.01;              ///< top-face pressure / E
  double membrane_thickness_ratio = 0.0;  ///< t / mean L' (calibrate::kDefaultThicknessRatio)
  std::vector<YoungsModulusRow> table1;
  std::vector<FrameRateRow> table2;
  double seconds = 0.0;
};

/// Table 1 for the three cubes and E = 100 Pa, 3.25 kPa.
std::vector<YoungsModulusRow> arnab2008_table1(double poisson_ratio = 0.3, double cube_size = 0.1,
                                               double strain_load = 0.01);
/// Table 2 for the three cubes and the 1 002-node sphere; `steps` timed steps per model.
std::vector<FrameRateRow> arnab2008_table2(double poisson_ratio = 0.3, int steps = 200);
/// Runs everything.
Arnab2008Report reproduce_arnab2008();
/// Writes `dir`/arnab2008.md and arnab2008.json (atomically).
void write_arnab2008_report(const std::filesystem::path& dir, const Arnab2008Report& report);

}  // namespace hooke::experiments
