// An octant of a closed box-shaped cavity (inner half-width A, wall T),
// for the refinement of walls in bending (scripts/thin_wall_study),
// whose flat walls bend under the cavity pressure.
// Physical groups: 1, 2, 3 the symmetry planes x = 0, y = 0, z = 0;
// 4 the cavity walls; 5 the outer face x = A + T; 6 the other outer faces.
SetFactory("OpenCASCADE");
DefineConstant[ h = 0.5, A = 5, T = 1 ];
B = A + T;
Box(1) = {0, 0, 0, B, B, B};
Box(2) = {0, 0, 0, A, A, A};
body() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; };
e = 1e-6;
xplane() = Surface In BoundingBox{-e, -e, -e, e, B + e, B + e};
yplane() = Surface In BoundingBox{-e, -e, -e, B + e, e, B + e};
zplane() = Surface In BoundingBox{-e, -e, -e, B + e, B + e, e};
inner()  = Surface In BoundingBox{-e, -e, -e, A + e, A + e, A + e};
inner() -= xplane();
inner() -= yplane();
inner() -= zplane();
xface()  = Surface In BoundingBox{B - e, -e, -e, B + e, B + e, B + e};
outer()  = Abs(Boundary{ Volume{body()}; });
outer() -= xplane();
outer() -= yplane();
outer() -= zplane();
outer() -= inner();
outer() -= xface();
Physical Surface(1) = {xplane()};
Physical Surface(2) = {yplane()};
Physical Surface(3) = {zplane()};
Physical Surface(4) = {inner()};
Physical Surface(5) = {xface()};
Physical Surface(6) = {outer()};
Physical Volume(1) = {body()};
Mesh.MeshSizeMax = h;
Mesh.MeshSizeMin = h;
