// Cylinder r = 1 cm, h = 2 cm (Lloyd et al. 2007, Fig. 15 and 18), in metres, axis along z, base at z = 0.
// Regenerate: gmsh -3 -nt 1 -format msh41 -setnumber h <size> cylinder.geo -o cylinder.msh
SetFactory("OpenCASCADE");
DefineConstant[ h = 0.0060 ];
Cylinder(1) = {0, 0, 0, 0, 0, 0.02, 0.01};
Mesh.CharacteristicLengthMax = h;
Mesh.CharacteristicLengthMin = h;
Mesh.Optimize = 1;
Physical Volume(1) = {1};
