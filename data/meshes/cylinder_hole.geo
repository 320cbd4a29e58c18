// Cylinder r = 1 cm, h = 2 cm with a centred spherical hole of radius 0.5 cm (Lloyd et al. 2007, Fig. 16),
// in metres, axis along z, base at z = 0. The paper does not give the hole radius; 0.5 cm is our choice.
SetFactory("OpenCASCADE");
DefineConstant[ h = 0.00201 ];
Cylinder(1) = {0, 0, 0, 0, 0, 0.02, 0.01};
Sphere(2) = {0, 0, 0.01, 0.005};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.CharacteristicLengthMax = h;
Mesh.CharacteristicLengthMin = h;
Mesh.Optimize = 1;
Physical Volume(1) = {3};
