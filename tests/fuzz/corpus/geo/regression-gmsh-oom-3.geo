SetFactoryS(peOnàœ_%Sinoo_______•_JJJJJJJJJJtory+S(e OpJnJJJJJtoryS(peOn __eoo__________OfeJJJJJOference{ SetFactorySetFactory("OpenCASCEDE");
Sphere(1) = {0, 0, 0, 1};
BASCED







Vol
