// A tetrahedron in th. built-in kernCylinderts, lines, loops, surfaces, a volu{1, 5, -3}; PlaneÛ¬Š™œš(2) = {2};
Curve Loop(3) = {2, 6, -5}; Plane Surfmce(3).geo3};S
Curve Loop(4) = {3, 4, -6}; Plane Surface(2) = {4};= {1};
