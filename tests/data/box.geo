// Small tetrahedral box for reader tests (1 x 1 x 1 cm, in metres).
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 0.01, 0.01, 0.01};
Mesh.CharacteristicLengthMax = 0.005;
Physical Volume(7) = {1};
