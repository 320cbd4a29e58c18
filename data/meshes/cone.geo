// Truncated cone, base radius 1 cm, top radius 0.4 cm, height 2 cm (Lloyd et al. 2007, Fig. 17), in metres,
// axis along z, base at z = 0. The paper gives no dimensions; these are our choice, with a flat top to load.
SetFactory("OpenCASCADE");
DefineConstant[ h = 0.0016 ];
Cone(1) = {0, 0, 0, 0, 0, 0.02, 0.01, 0.004};
Mesh.CharacteristicLengthMax = h;
Mesh.CharacteristicLengthMin = h;
Mesh.Optimize = 1;
Physical Volume(1) = {1};
