// trace(), min_extent() and max_extent() on cylinders, cones and discs: the
// side, both end discs (from outside and from inside), open ones (no end
// discs: the ray goes on to the inner side), transformed ones, a cone whose
// radii have opposite signs (two cones point to point), a disc's hole, and
// misses; the boxes are POV-Ray's (the shape's own box turned and moved
// with it). quadrics.pov.err is the #debug output of povray 3.7.0.10 for this
// file (povray-debug: same).
#version 3.7;
global_settings { assumed_gamma 1 }
// (what rounds to 0 is printed as 0, not as POV-Ray's -0.0000)
#macro Snap(V)
  <(abs(V.x) < 1e-9 ? 0 : V.x), (abs(V.y) < 1e-9 ? 0 : V.y), (abs(V.z) < 1e-9 ? 0 : V.z)>
#end
#macro Show(Name, Obj, From, Dir)
  #local N = <9, 9, 9>;
  #local P = trace(Obj, From, Dir, N);
  #debug concat(Name, ": ", vstr(3, Snap(P), ", ", 0, 4), " normal ", vstr(3, Snap(N), ", ", 0, 4), "\n")
#end
#macro Box(Name, Obj)
  #debug concat(Name, " box: ", vstr(3, Snap(min_extent(Obj)), ", ", 0, 4), " to ",
                vstr(3, Snap(max_extent(Obj)), ", ", 0, 4), "\n")
#end
#declare C = cylinder { <0, 0, 0>, <0, 2, 0>, 1 }
Show("cylinder side", C, <-5, 1, 0>, x)
Show("cylinder cap", C, <0.5, 5, 0>, -y)
Show("cylinder base", C, <0.5, -5, 0.2>, y)
Show("cylinder rim, inside", C, <0, 1, 0>, <1, 1, 0>)
Show("cylinder cap, inside", C, <0, 1, 0>, <0.1, 1, 0>)
Show("cylinder miss", C, <-5, 3, 0>, x)
Show("open cylinder", cylinder { <0, 0, 0>, <0, 2, 0>, 1 open }, <0.5, 5, 0>, -y)
Show("open cylinder, oblique", cylinder { <0, 0, 0>, <0, 2, 0>, 1 open }, <-0.5, 5, 0>, <1, -3, 0>)
Show("cylinder tilted", cylinder { <-1, -1, 0>, <1, 1, 1>, 0.5 scale <1, 2, 1> rotate 30 * z }, <0, 5, -5>, <0, -1, 1>)
Show("cylinder radius -1", cylinder { <0, 0, 0>, <0, 2, 0>, -1 }, <-5, 1, 0>, x)
Box("cylinder", C)
Box("cylinder tilted", cylinder { <-1, -1, 0>, <1, 1, 1>, 0.5 rotate 30 * z })
#declare K = cone { <0, 0, 0>, 1, <0, 2, 0>, 0.5 }
Show("cone side", K, <-5, 1, 0>, x)
Show("cone cap", K, <0.2, 5, 0>, -y)
Show("cone base", K, <0.8, -5, 0>, y)
Show("cone cap miss", K, <0.7, 5, 0>, -y)
Show("cone from inside", K, <0, 1, 0>, <1, 0.2, 0.3>)
Show("open cone", cone { <0, 0, 0>, 1, <0, 2, 0>, 0.5 open }, <0.2, 5, 0>, -y)
Show("open cone, inside", cone { <0, 0, 0>, 0.5, <0, 2, 0>, 1 open }, <0, 5, 0>, <0.3, -1, 0>)
Show("cone to a point", cone { <0, 0, 0>, 1, <0, 2, 0>, 0 }, <-5, 1.5, 0.1>, x)
Show("cone reversed", cone { <0, 2, 0>, 0.5, <0, 0, 0>, 1 }, <-5, 1, 0>, x)
Show("cone -1 to 1, waist", cone { <0, 0, 0>, -1, <0, 2, 0>, 1 }, <-5, 1, 0.05>, x)
Show("cone -1 to 1, below", cone { <0, 0, 0>, -1, <0, 2, 0>, 1 }, <-5, 0.5, 0>, x)
Show("cone transformed", cone { <0, 0, 0>, 1, <0, 0, 3>, 0.2 scale <1, 0.5, 1> rotate 40 * x translate y }, <0, 5, 1>, -y)
Box("cone", K)
Box("cone tilted", cone { <0, 0, 0>, 1, <1, 2, 0.5>, 0.3 })
Box("cone -1 to 1", cone { <0, 0, 0>, -1, <0, 2, 0>, 1 })
#declare D = disc { <0, 1, 0>, <0, 2, 0>, 1.5, 0.5 }
Show("disc", D, <1, 5, 0>, -y)
Show("disc from below", D, <0, -5, 1>, y)
Show("disc hole", D, <0.2, 5, 0>, -y)
Show("disc outside", D, <1.6, 5, 0>, -y)
Show("disc tilted", disc { <0, 0, 0>, <1, 1, 0>, 1 scale <2, 1, 1> translate z }, <-5, 0, 1>, x)
Show("disc radius -1", disc { <0, 0, 0>, z, -1 }, <0.5, 0.5, -5>, z)
Box("disc", D)
Box("disc tilted", disc { <0, 0, 0>, <1, 1, 0>, 1 scale <2, 1, 1> translate z })
camera { location <0, 0, -5> look_at 0 }
sphere { 0, 1 pigment { rgb 1 } }
