SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Physical Surface("bottom") = Surface In BoundingBox{-0.01, -0.01, -0.01, 2.01, 1.01, 0.01};
