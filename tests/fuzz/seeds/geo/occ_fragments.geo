SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 0.5, 1};
Box(2) = {-0.2, -0.2, 0, 0.4, 0.4, 0.5};
v() = BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; };
