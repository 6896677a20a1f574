// An octant of a thick-walled sphere (inner radius A, outer radius B) for
// the closed-form inflation of an incompressible neo-Hookean shell.
//
// Physical groups: 1, 2, 3 the symmetry planes x = 0, y = 0, z = 0;
// 4 the inner (pressurized) surface; 5 the outer surface; Volume 1.

SetFactory("OpenCASCADE");

DefineConstant[
  h = 0.25,   // mesh size
  A = 1,      // inner radius
  B = 2       // outer radius
];

Sphere(1) = {0, 0, 0, B};
Sphere(2) = {0, 0, 0, A};
Box(3) = {0, 0, 0, 2 * B, 2 * B, 2 * B};
shell() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; };
octant() = BooleanIntersection{ Volume{shell()}; Delete; }{ Volume{3}; Delete; };

e = 1e-6;
xplane() = Surface In BoundingBox{-e, -e, -e, e, B + e, B + e};
yplane() = Surface In BoundingBox{-e, -e, -e, B + e, e, B + e};
zplane() = Surface In BoundingBox{-e, -e, -e, B + e, B + e, e};
inner()  = Surface In BoundingBox{-e, -e, -e, A + e, A + e, A + e};
outer()  = Abs(Boundary{ Volume{octant()}; });
outer() -= xplane();
outer() -= yplane();
outer() -= zplane();
outer() -= inner();

Physical Surface(1) = {xplane()};
Physical Surface(2) = {yplane()};
Physical Surface(3) = {zplane()};
Physical Surface(4) = {inner()};
Physical Surface(5) = {outer()};
Physical Volume(1)  = {octant()};

Mesh.MeshSizeMax = h;
Mesh.MeshSizeMin = h / 4;
