# The README's main job, end to end: hooke reproduce lloyd2007 writes the Markdown report, the JSON with every
# number, and every figure as a PNG; the report puts the paper's numbers beside ours.
include(${CMAKE_CURRENT_LIST_DIR}/reproduce_common.cmake)
run_reproduce(lloyd2007 lloyd2007.md lloyd2007.json figures/fig01_force_displacement.png figures/fig03_error_vs_nu.png
              figures/fig09_membrane.png figures/fig10_triangles_eq8.png figures/fig11_triangles_eq9.png
              figures/fig12_squares.png figures/fig13_resolution_shear.png figures/fig14_two_layer_text.png
              figures/fig15_cylinder.png figures/fig16_cylinder_hole.png figures/fig17_cone.png
              figures/fig18_cylinder_volume.png)
require_in_report(lloyd2007.md "| sec5.6-cylinder-stretch |" "0.039 / 0.013" "stiffness-fit" "factor of 2" "figures/fig15_cylinder.png")
