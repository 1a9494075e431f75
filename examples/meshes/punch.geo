// punch.geo: a flat punch, 2 wide x 1 tall, whose bottom corners are rounded with radius 0.25,
// to be pressed onto and slid along a flat rigid obstacle (examples/scenes/punch.toml).
// Lengths in the scene's unit (mm). The bottom runs from (-1, 0.25) down the left arc, along the
// flat y = 0 for |x| <= 0.75, and up the right arc to (1, 0.25); the top edge is y = 1.
// Exact area: 2 - 2 r^2 (1 - pi/4) with r = 0.25, i.e. 1.97317477042468...
//
// Regenerate punch.msh (Gmsh 4.8.4, Debian 12 package `gmsh`), from this folder:
//   gmsh -2 -format msh41 punch.geo -o punch.msh
// (the options below already ask for MSH 4.1 ASCII with physical groups only).

r = 0.25;      // corner radius
h_low = 0.045; // element size along the bottom, where contact happens
h_high = 0.1;  // element size at the top

Point(1) = {-1 + r, 0, 0, h_low};   // flat bottom, left end
Point(2) = { 1 - r, 0, 0, h_low};   // flat bottom, right end
Point(3) = { 1,     r, 0, h_low};   // right arc, upper end
Point(4) = { 1,     1, 0, h_high};
Point(5) = {-1,     1, 0, h_high};
Point(6) = {-1,     r, 0, h_low};   // left arc, upper end
Point(7) = { 1 - r, r, 0, h_low};   // right arc centre
Point(8) = {-1 + r, r, 0, h_low};   // left arc centre

Line(1) = {1, 2};         // flat bottom
Circle(2) = {2, 7, 3};    // right rounded corner
Line(3) = {3, 4};         // right side
Line(4) = {4, 5};         // top
Line(5) = {5, 6};         // left side
Circle(6) = {6, 8, 1};    // left rounded corner

Curve Loop(1) = {1, 2, 3, 4, 5, 6};  // counter-clockwise: the surface normal is +z
Plane Surface(1) = {1};

Physical Curve("top") = {4};
Physical Curve("bottom") = {6, 1, 2};
Physical Surface("body") = {1};

Mesh.MshFileVersion = 4.1;
Mesh.Binary = 0;
Mesh.SaveAll = 0;       // write only the elements of physical groups
Mesh.Algorithm = 6;     // Frontal-Delaunay: well-shaped triangles
Mesh.ElementOrder = 1;  // P1 triangles
