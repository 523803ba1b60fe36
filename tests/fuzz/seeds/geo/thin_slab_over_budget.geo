SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1000, 1000, 0.01};
