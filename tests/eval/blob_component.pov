// trace() and inside() of blobs whose components have transformations of
// their own: moved, turned and uniformly scaled ones, and unevenly scaled ones
// (POV-Ray's ellipsoidal components and stretched cylinders), in a blob that
// is itself transformed. blob_component.pov.err is the #debug output of
// povray 3.7.0.10 for this file (povray-debug: same).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare B = blob {
	threshold 0.5
	sphere { 0, 1, 1 scale <2, 0.5, 1> rotate z * 30 }
	sphere { <0.5, 0, 0>, 0.5, 1 scale 2 translate y }
	cylinder { 0, y, 0.4, 1 scale <1, 2, 0.5> rotate x * 90 translate <0, 0, 0.5> }
	sphere { <0, -0.3, 0>, 0.5, -1 pigment { rgb 1 } rotate z * 45 }
	rotate y * 20 translate <0.1, 0, 0>
}
#declare Points = array[6] { <0, 0, 0>, <1.3, 0.7, 0>, <0, 0.4, 0>, <0.9, 1, 0>, <-0.3, 0, 0>, <0.1, 0.1, 1> }
#for (K, 0, 5)
	#debug concat("<", vstr(3, Points[K], ", ", 0, 1), ">: ", str(inside(B, Points[K]), 0, 0), "\n")
#end
#declare Rays = array[5] { <-5, 0.1, 0.05>, <5, 0.5, 0.1>, <0.2, 5, 0.1>, <0.1, 0.2, -5>, <0.1, -5, 0.3> }
#for (K, 0, 4)
	#declare N = <0, 0, 0>;
	#declare P = trace(B, Rays[K], -Rays[K], N);
	#debug concat("from <", vstr(3, Rays[K], ", ", 0, 2), ">: <", vstr(3, P, ", ", 0, 4), ">\n")
	#debug concat("  normal <", vstr(3, N, ", ", 0, 4), ">\n")
#end
object { B }   // POV-Ray wants an object in a scene
