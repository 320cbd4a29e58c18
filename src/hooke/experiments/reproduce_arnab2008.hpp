#pragma once
/// The experiments of Arnab & Raja ("A Deformable Surface Model for Soft Volume Simulation") as data: each
/// table is a function that builds its meshes, runs its cases and returns our numbers beside the paper's.
#include <filesystem>
#include <hooke/experiments/figure.hpp>
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

/// Fig. 10: volume deviation under a constant point force, per scheme.
struct VolumeDeviationRow {
  std::string scheme;                     ///< "A".."D"
  std::vector<double> force;              ///< N, the point force magnitudes
  std::vector<double> deviation_percent;  ///< 100 |V - V0| / V0 at each force
  double average_percent = 0.0;           ///< mean over the forces
};

/// Fig. 8: the displacement pattern around a loaded node before and after a local refinement.
struct RefinementRow {
  std::string scheme;                  ///< "C" or "D"
  double force = 0.0;                  ///< N
  double standard_deviation_mm = 0.0;  ///< std of (|u_refined| - |u_coarse|) over the compared nodes, mm
  double mean_deviation_mm = 0.0;      ///< mean of ||u_refined| - |u_coarse||, mm
  double peak_displacement_mm = 0.0;   ///< |u| of the loaded node on the coarse mesh, mm
  int compared_nodes = 0;
};

/// Fig. 12: a cube sheared on its top face, bottom face fixed: the surface model against the linear FEM of the
/// tetrahedralised cube, node by node on the surface.
struct ShearComparison {
  int surface_nodes = 0, fem_nodes = 0;
  double youngs_modulus = 0.0, shear_stress = 0.0;  ///< Pa
  double fem_max_mm = 0.0, surface_max_mm = 0.0;    ///< largest node displacement of each, mm
  double max_error_mm = 0.0, mean_error_mm = 0.0;   ///< node distance surface model - FEM, over the surface nodes
  double top_mean_error_mm = 0.0;                   ///< the same over the sheared face
};

/// Fig. 9: the sphere under gravity. With world anchors a uniform sphere should sag uniformly (rho g L'^2 / E
/// per node); the spread of the nodes' vertical displacement measures how far a scheme is from that.
struct GravityRow {
  std::string scheme;               ///< "B" or "D"
  double mean_sag_mm = 0.0;         ///< mean downward displacement over the nodes, mm
  double sag_spread_percent = 0.0;  ///< 100 x std / mean of the downward displacement
  double volume_deviation_percent = 0.0;
};

/// Fig. 11: a push on the top node of the sphere (scheme D) with uniform weights and with the run-time weights of
/// Eq. 4: where the volume penalty moves the body.
struct WeightsRow {
  std::string weights;              ///< "uniform" or "run-time"
  double pushed_node_mm = 0.0;      ///< downward displacement of the pushed node, mm
  double opposite_pole_mm = 0.0;    ///< downward displacement of the opposite (bottom) pole, mm
  double equator_outward_mm = 0.0;  ///< mean outward radial displacement of the equator nodes, mm
  double volume_deviation_percent = 0.0;
};

struct Arnab2008Report {
  double poisson_ratio = 0.3;   ///< nu used throughout (the paper gives none)
  double cube_size = 0.1;       ///< cube edge, m
  double strain_load = 0.01;    ///< top-face pressure / E
  double membrane_ratio = 0.0;  ///< membrane springs / anchors (calibrate::kMembraneRatio): t = ratio x A / L'
  std::vector<YoungsModulusRow> table1;
  std::vector<FrameRateRow> table2;
  std::vector<VolumeDeviationRow> fig10;
  std::vector<RefinementRow> fig8;
  ShearComparison fig12;
  std::vector<GravityRow> fig9;
  std::vector<WeightsRow> fig11;
  std::vector<Figure> figures;                     ///< drawn by scripts/plot_figures.py into figures/<name>.png
  int sphere_nodes = 0, refined_sphere_nodes = 0;  ///< Fig. 8's sphere before and after refinement
  double seconds = 0.0;
};

/// Table 1 for the three cubes and E = 100 Pa, 3.25 kPa.
std::vector<YoungsModulusRow> arnab2008_table1(double poisson_ratio = 0.3, double cube_size = 0.1,
                                               double strain_load = 0.01);
/// Table 2 for the three cubes and the 1 002-node sphere; `steps` timed steps per model.
std::vector<FrameRateRow> arnab2008_table2(double poisson_ratio = 0.3, int steps = 200);
/// Fig. 10 on a sphere of 5 cm (E = 100 Pa): a downward force on the top node, schemes A-D.
std::vector<VolumeDeviationRow> arnab2008_fig10(double poisson_ratio = 0.3);
/// Fig. 8 on the same sphere (E = 10 Pa, the paper's): refine around the top node, compare the displacement of
/// the original nodes within 2 cm of it, schemes C and D, over force magnitudes. Fills the node counts.
std::vector<RefinementRow> arnab2008_fig8(double poisson_ratio, int& sphere_nodes, int& refined_nodes);
/// Fig. 12 on the 602-node cube (E = 3.25 kPa), a shear stress of 5 % of E along x on the top face. With
/// `figure`, also the side view of both deformed shapes (FEM black, surface model red).
ShearComparison arnab2008_fig12(double poisson_ratio, Figure* figure = nullptr);
/// Fig. 9 on the 5 cm sphere (E = 10 kPa, so that it sags by about 5 % of its radius; 1000 kg/m^3), schemes B, D.
/// With `figure`, also side views of both deformed shapes (displacements magnified 20 times).
std::vector<GravityRow> arnab2008_fig9(double poisson_ratio, Figure* figure = nullptr);
/// Fig. 11 on the 5 cm sphere (E = 100 Pa), a 5 mN push on the top node.
/// With `figure`, also side views of both deformed shapes.
std::vector<WeightsRow> arnab2008_fig11(double poisson_ratio, Figure* figure = nullptr);
/// Runs everything.
Arnab2008Report reproduce_arnab2008();
/// Curve figures of Fig. 8 and Fig. 10 from their rows.
std::vector<Figure> arnab2008_curve_figures(const Arnab2008Report& report);
/// Writes `dir`/arnab2008.md and arnab2008.json and the figure specs `dir`/figures/<name>.json (atomically).
void write_arnab2008_report(const std::filesystem::path& dir, const Arnab2008Report& report);

}  // namespace hooke::experiments
