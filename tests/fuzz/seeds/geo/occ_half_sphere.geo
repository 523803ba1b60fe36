SetFactory("OpenCASCADE");
Sphere(1) = {0, 0, 0, 1};
Box(2) = {-1, -1, -1, 2, 2, 1};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Physical Surface("cut") = Surface In BoundingBox{-1.1, -1.1, -0.01, 1.1, 1.1, 0.01};
