For i In {1:3}
Point(i) = {i, 0, 0};
EndFor
