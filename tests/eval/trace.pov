// trace() on eclat's shapes, transformed, with the normal it gives back and a
// miss (<0,0,0> for both); a triangle's normal faces the ray; the smooth
// triangle's normals have one length (eclat normalizes them, POV-Ray does
// not before it interpolates); trace.pov.err is the #debug output of povray
// 3.7.0.10 for this file (povray-debug: same).
#version 3.7;
global_settings { assumed_gamma 1 }
#macro Show(Name, Obj, From, Dir)
  #local N = <9, 9, 9>;
  #local P = trace(Obj, From, Dir, N);
  #debug concat(Name, ": ", vstr(3, P, ", ", 0, 4), " normal ", vstr(3, N, ", ", 0, 4), "\n")
#end
Show("sphere", sphere { <0, 1, 0>, 1 scale <2, 1, 1> translate x }, <0, 10, 0>, -y)
Show("sphere from inside", sphere { 0, 2 }, <0, 0, 0>, <1, 1, 0>)
Show("box", box { -1, 1 rotate 45 * y }, <-5, 0.5, 0>, x)
Show("plane", plane { <0, 1, 1>, 1 }, <0, 5, -3>, <0, -1, 0.5>)
Show("triangle", triangle { <0, 0, 0>, <2, 0, 0>, <0, 0, 2> translate y }, <0.5, 5, 0.5>, -y)
Show("smooth_triangle", smooth_triangle { <0, 0, 0>, <0, 1, 0>, <2, 0, 0>, <0.6, 0.8, 0>, <0, 0, 2>, <0, 0.8, 0.6> },
     <0.5, 5, 0.5>, -y)
Show("mesh", mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } triangle { <0, 0, 1>, <1, 0, 1>, <0, 1, 1> }
                    scale 2 }, <0.2, 0.2, -5>, z)
Show("union", union { sphere { <0, 0, 3>, 1 } box { <-1, -1, 5>, <1, 1, 6> } }, <0, 0, 10>, -z)
Show("miss", sphere { 0, 1 }, <0, 5, 0>, y)
camera { location <0, 0, -5> look_at 0 }
sphere { 0, 1 pigment { rgb 1 } }
