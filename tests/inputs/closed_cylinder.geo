// A cylinder along x (radius 8, height 20 mm) clamped at x = 0, with a
// closed cavity (radius 5, from x = 2 to 17): a body a two-part mold split
// through its axis releases without undercuts (tests/mold.sh).
SetFactory("OpenCASCADE");
DefineConstant[h = {2, Name "h"}];
Cylinder(1) = {0, 0, 0, 20, 0, 0, 8};
Cylinder(2) = {2, 0, 0, 15, 0, 0, 5};
BooleanDifference(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
Physical Volume(1) = {3};
e = 1e-3;
base()   = Surface In BoundingBox{-e, -8 - e, -8 - e, e, 8 + e, 8 + e};
cavity() = Surface In BoundingBox{2 - e, -5 - e, -5 - e, 17 + e, 5 + e, 5 + e};
all()    = Boundary{Volume{3};};
Physical Surface(1) = {base()};
Physical Surface(2) = {cavity()};
Physical Surface(3) = {all()};
Physical Surface(3) -= {base(), cavity()};
Mesh.MeshSizeMax = h;
Mesh.MeshSizeFromCurvature = 16;
