// A block clamped at z = 0 with a closed cavity (y from 2 to 5) and, beyond
// a wall 0.6 mm thick, a slot 0.4 mm wide open at the top (y from 5.6 to
// 6): inflating the cavity bulges the wall across the slot until it
// touches the far side (castability: deformed self-contact).
SetFactory("OpenCASCADE");
DefineConstant[h = {1.5, Name "h"}];
Box(1) = {0, 0, 0, 10, 10, 10};
Box(2) = {2, 2, 2, 6, 3, 6};
Box(3) = {1, 5.6, 3, 8, 0.4, 8};
BooleanDifference(4) = {Volume{1}; Delete;}{Volume{2, 3}; Delete;};
Physical Volume(1) = {4};
e = 1e-3;
bottom() = Surface In BoundingBox{-e, -e, -e, 10 + e, 10 + e, e};
cavity() = Surface In BoundingBox{2 - e, 2 - e, 2 - e, 8 + e, 5 + e, 8 + e};
all() = Boundary{Volume{4};};
Physical Surface(1) = {bottom()};
Physical Surface(2) = {cavity()};
Physical Surface(3) = {all()};
Physical Surface(3) -= {bottom(), cavity()};
MeshSize{:} = h;
