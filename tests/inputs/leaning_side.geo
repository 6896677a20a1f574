// A frustum along x (radius 8 at the clamped base x = 0, its side leaning
// in by 13 degrees to radius 8 - 10 tan(13 deg) at x = 10) with a closed
// cavity (radius 3, from x = 2 to 8): walls of 2 mm at the base and the
// cap, more elsewhere. Near the base's rim the rays along the tilted
// normals leave through the neighbouring face 13 degrees from grazing
// (tests/castability.sh): corners, not walls.
SetFactory("OpenCASCADE");
DefineConstant[h = {1, Name "h"}];
Cone(1) = {0, 0, 0, 10, 0, 0, 8, 8 - 10 * Tan(13 * Pi / 180)};
Cylinder(2) = {2, 0, 0, 6, 0, 0, 3};
BooleanDifference(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
Physical Volume(1) = {3};
e = 1e-3;
base()   = Surface In BoundingBox{-e, -8 - e, -8 - e, e, 8 + e, 8 + e};
cavity() = Surface In BoundingBox{2 - e, -3 - e, -3 - e, 8 + e, 3 + e, 3 + e};
all()    = Boundary{Volume{3};};
Physical Surface(1) = {base()};
Physical Surface(2) = {cavity()};
Physical Surface(3) = {all()};
Physical Surface(3) -= {base(), cavity()};
Mesh.MeshSizeMax = h;
Mesh.MeshSizeFromCurvature = 16;
