// Small planar square for reader tests (2 x 2 cm, in metres); -setnumber quads 1 recombines into quads.
DefineConstant[ quads = 0 ];
Point(1) = {0, 0, 0, 0.006};
Point(2) = {0.02, 0, 0, 0.006};
Point(3) = {0.02, 0.02, 0, 0.006};
Point(4) = {0, 0.02, 0, 0.006};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
If (quads)
  Recombine Surface{1};
EndIf
Physical Surface(3) = {1};
