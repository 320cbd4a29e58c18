// Rectangle 4 cm wide, 5 cm high, meshed with unstructured triangles (Lloyd et al. 2007, Sec. 5.2, Fig. 10-11:
// "a rectangular object meshed with a triangle meshing tool"; the paper gives no size). Metres, base at y = 0.
// Regenerate: gmsh -2 -nt 1 -format msh41 rectangle_tri.geo -o rectangle_tri.msh
DefineConstant[ h = 0.0075 ];
Point(1) = {0, 0, 0, h};
Point(2) = {0.04, 0, 0, h};
Point(3) = {0.04, 0.05, 0, h};
Point(4) = {0, 0.05, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh.Algorithm = 5;  // Delaunay
Physical Surface(1) = {1};
