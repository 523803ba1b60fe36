// The substrate under the spread cell (lengths in micrometres): a 24 x 24 x 4.5 um
// block of 24 x 24 x 4 hexahedra, its top face 0.4776 um below the cell (the contact's
// equilibrium gap). substrate.msh is this file meshed by Gmsh 4.8 (its API:
// gmsh::open, gmsh::model::mesh::generate(3), gmsh::write; or `gmsh -3` where the
// Gmsh program is installed); the scene reads the .msh.
SetFactory("OpenCASCADE");
Box(1) = {-12, -12, -4.9776, 24, 24, 4.5};
Transfinite Curve{:} = 25;
// The four vertical edges: 5 nodes through the thickness.
vertical() = Curve In BoundingBox{-12.1, -12.1, -5, -11.9, -11.9, -0.4};
vertical() += Curve In BoundingBox{11.9, -12.1, -5, 12.1, -11.9, -0.4};
vertical() += Curve In BoundingBox{-12.1, 11.9, -5, -11.9, 12.1, -0.4};
vertical() += Curve In BoundingBox{11.9, 11.9, -5, 12.1, 12.1, -0.4};
Transfinite Curve{vertical()} = 5;
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{1};
Physical Volume("substrate") = {1};
Physical Surface("top") = Surface In BoundingBox{-12.1, -12.1, -0.48, 12.1, 12.1, -0.47};
Physical Surface("base") = Surface In BoundingBox{-12.1, -12.1, -4.98, 12.1, 12.1, -4.97};
