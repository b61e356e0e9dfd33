// trace() on tori and superellipsoids, transformed, with the normal it gives
// back: from outside, from inside the tube, through the hole (a miss), along
// the axis of a spindle torus (whose first hit is the outer surface's
// dimple), and a superellipsoid from outside and inside, edge-on to a flat
// face; and their boxes, min_extent() and max_extent(). trace_torus.pov.err
// is the #debug output of povray 3.7.0.10 for this file (povray-debug: same).
#version 3.7;
global_settings { assumed_gamma 1 }
#macro Show(Name, Obj, From, Dir)
  #local N = <9, 9, 9>;
  #local P = trace(Obj, From, Dir, N);
  #debug concat(Name, ": ", vstr(3, P, ", ", 0, 4), " normal ", vstr(3, N, ", ", 0, 4), "\n")
#end
Show("torus", torus { 2, 0.5 }, <0, 5, 0.2>, <0.3, -1, 0.1>)
Show("torus turned", torus { 1, 0.3 sturm rotate <30, 20, 10> translate <1, 2, 3> }, <-4, 1, 0>, <5, 1.2, 3>)
Show("torus scaled", torus { 1, 0.3 scale <2, 1, 0.5> }, <-5, 0.1, 0>, x)
Show("torus from inside the tube", torus { 2, 0.5 }, <2, 0, 0>, <0.2, 0.3, 1>)
Show("torus through the hole", torus { 2, 0.5 }, <0, 5, 0>, -y)
Show("torus across the hole", torus { 2, 0.5 }, <-5, 0.1, 0>, x)
Show("spindle torus", torus { 0.6, 1 }, <0.05, 5, 0>, -y)
Show("spindle, side", torus { 0.6, 1 rotate x * 90 }, <0.3, -4, 0.2>, <0, 1, 0.1>)
Show("superellipsoid", superellipsoid { <0.3, 0.6> }, <0.5, 4, 0.3>, -y)
Show("superellipsoid turned", superellipsoid { <2.5, 0.5> scale <2, 1, 1> rotate <10, 40, 0> translate x }, <-3, 0.5, -4>, <1, 0, 1>)
Show("superellipsoid from inside", superellipsoid { <1, 1> scale 2 }, <0.2, 0.1, 0>, <1, 1, 1>)
Show("superellipsoid miss", superellipsoid { <3, 3> }, <0.9, 0.9, -5>, z)
// their boxes: POV-Ray's, a torus's tight, a superellipsoid's 1.0001 wide
#macro Extent(Name, Obj)
  #debug concat(Name, " box: ", vstr(3, min_extent(Obj), ", ", 0, 4), " to ", vstr(3, max_extent(Obj), ", ", 0, 4), "\n")
#end
Extent("torus", torus { 2, 0.5 scale <1, 2, 1> translate x })
Extent("torus turned", torus { 1, 0.3 rotate x * 90 })
Extent("superellipsoid", superellipsoid { <0.3, 0.6> scale <2, 1, 1> translate y })
camera { location <0, 0, -5> look_at 0 }
sphere { 0, 1 pigment { rgb 1 } }
