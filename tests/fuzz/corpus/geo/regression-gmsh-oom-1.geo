SeSetF













{0, 0, 0,E");Hideere(1) z 






























˚ı







J





{"(
O

{"(OpenCASCAD[");
BGmsh/}Input fileacïêry("Physical PointOtFactenCASCA?Eo"r