// Sphere of radius 1 cm centred at the origin, in metres (Arnab & Raja, Fig. 8 and Table 2).
// Surface mesh: gmsh -2 ...; volume mesh: gmsh -3 ...
SetFactory("OpenCASCADE");
DefineConstant[ h = 0.00128 ];
Sphere(1) = {0, 0, 0, 0.01};
Mesh.CharacteristicLengthMax = h;
Mesh.CharacteristicLengthMin = h;
Mesh.Optimize = 1;
Physical Volume(1) = {1};
Physical Surface(2) = {1};
