// A hollow box and a second box that overlaps it, meshed apart: the
// surface of the body passes through itself (self_intersecting.prm).
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 10, 10, 10};
Sphere(2) = {5, 5, 5, 3};
BooleanDifference(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
Box(4) = {7, 7, 7, 8, 8, 8};
Physical Volume(1) = {3, 4};
s() = Boundary{Volume{3};};
t() = Boundary{Volume{4};};
Physical Surface(1) = {s(0)};       // x = 0 of the hollow box: clamped
Physical Surface(2) = {s(#s() - 1)}; // the spherical cavity: pressurized
Physical Surface(3) = {s({1:#s() - 2}), t()}; // the rest: design
