// A spread cell (lengths in micrometres; the scene scales by 1e-6): a flat lamella,
// 8 um in radius and 0.6 um thick, around a dome 3.5 um in radius and 2.45 um high
// over the nucleus. Physical surfaces: "bottom" (the flat underside, facing the
// substrate) and "top" (the free surface, everything else).
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 0.6, 8};
Sphere(2) = {0, 0, 0, 3.5};
Dilate {{0, 0, 0}, {1, 1, 0.7}} { Volume{2}; }
Box(3) = {-4, -4, -4, 8, 8, 4};
BooleanDifference(4) = { Volume{2}; Delete; }{ Volume{3}; Delete; };
BooleanUnion(5) = { Volume{1}; Delete; }{ Volume{4}; Delete; };

Physical Volume("cell") = {5};
bottom() = Surface In BoundingBox{-8.1, -8.1, -0.01, 8.1, 8.1, 0.01};
top() = Boundary{ Volume{5}; };
top() -= bottom();
Physical Surface("bottom") = {bottom()};
Physical Surface("top") = {top()};
