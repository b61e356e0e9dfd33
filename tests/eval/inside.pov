// inside() of shapes, a blob, a transformed object and CSG: inside.pov.err is
// the #debug output of povray 3.7.0.10 for this file (povray-debug: same).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare B = blob { threshold 0.5 sphere { 0, 1, 1 } sphere { x, 1, 1 } cylinder { <0, 0, 0>, <0, 2, 0>, 0.5, 1 } }
#declare D = difference { box { -1, 1 } sphere { 0, 0.5 } }
#declare M = merge { sphere { 0, 1 } torus { 1, 0.2 } scale <2, 1, 1> rotate z * 90 translate y }
#declare I = intersection { cylinder { -2 * y, 2 * y, 1 } plane { y, 0.5 } }
#declare T = torus { 1, 0.25 rotate x * 90 }
#declare Points = array[6] { <0.6, 0, 0>, <3, 0, 0>, <0, 1.6, 0>, <0.8, 0.8, 0>, <0, 0, 0>, <1, 1.9, 0> }
#for (K, 0, 5)
	#debug concat("<", vstr(3, Points[K], ", ", 0, 1), ">: ",
	              str(inside(B, Points[K]), 0, 0), str(inside(D, Points[K]), 0, 0), str(inside(M, Points[K]), 0, 0),
	              str(inside(I, Points[K]), 0, 0), str(inside(T, Points[K]), 0, 0), "\n")
#end
object { B }   // POV-Ray wants an object in a scene
