// The initial actuator of the paper (Table I), in mm, axis along x:
// an outer cylinder of radius R and height H, clamped at x = 0, with a closed
// lower cavity (radius r, height H1, above a base of thickness T) and an open
// top cavity (radius r, depth H2). The plate between the cavities is
// H - T - H1 - H2 thick (1.5 mm, the wall thickness R - r, by default).
//
// Physical groups (the boundary ids of the parameter files):
//   1  clamped base (x = 0)
//   2  walls of the closed, pressurized cavity
//   3  design surface: the cylindrical wall of the open top cavity
//   4  every other surface (outer wall, top rim, floor of the top cavity)
//   Physical Volume 1: the elastomer
//
// softopt meshes this with: gmsh -3 -setnumber h <Mesh size> actuator.geo

SetFactory("OpenCASCADE");

DefineConstant[
  h  = 2,      // mesh size
  r  = 10,     // inner radius
  R  = 11.5,   // outer radius
  H  = 60,     // total height
  H1 = 47,     // pressurized cavity height
  H2 = 10,     // top cavity depth
  T  = 1.5     // base thickness below the pressurized cavity
];

Cylinder(1) = {0, 0, 0, H, 0, 0, R};
Cylinder(2) = {T, 0, 0, H1, 0, 0, r};
Cylinder(3) = {H - H2, 0, 0, H2 + 1, 0, 0, r};
body() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2, 3}; Delete; };

e = 1e-3;
base()   = Surface In BoundingBox{-e, -R - e, -R - e, e, R + e, R + e};
cavity() = Surface In BoundingBox{T - e, -r - e, -r - e, T + H1 + e, r + e, r + e};
top()    = Surface In BoundingBox{H - H2 - e, -r - e, -r - e, H + e, r + e, r + e};
floor()  = Surface In BoundingBox{H - H2 - e, -r - e, -r - e, H - H2 + e, r + e, r + e};
design() = top();
design() -= floor();
other()  = Abs(Boundary{ Volume{body()}; });
other() -= base();
other() -= cavity();
other() -= design();

Physical Surface(1) = {base()};
Physical Surface(2) = {cavity()};
Physical Surface(3) = {design()};
Physical Surface(4) = {other()};
Physical Volume(1)  = {body()};

Mesh.MeshSizeMax = h;
Mesh.MeshSizeMin = h / 4;
Mesh.MeshSizeFromCurvature = 24;
