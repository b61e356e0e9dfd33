// Splines, with POV-Ray 3.7's four interpolations, inside, before and after
// the points, points given out of order and a time given twice; spline.pov.err
// is the #debug output of povray 3.7.0.10 for this file (povray-debug: same).
#version 3.7;
global_settings { assumed_gamma 1 }
#macro Show(Name, S)
  #local T = -0.5;
  #while (T <= 4.5)
    #debug concat(Name, " ", str(T, 0, 2), ": ", vstr(3, S(T), ", ", 0, 4), "\n")
    #local T = T + 0.75;
  #end
#end
#declare Points = spline {
  0, <0, 0, 0>
  2, <2, 1, 0>
  1, <1, 3, 1>
  3, <4, 0, 2>
  4, <3, -1, 1>
  3, <5, 0, 2>
}
Show("linear", Points)
Show("quadratic", spline { Points quadratic_spline })
Show("cubic", spline { cubic_spline 0, <0, 0, 0> 1, <1, 3, 1> 2, <2, 1, 0> 3, <5, 0, 2> 4, <3, -1, 1> })
Show("natural", spline { natural_spline 0, <0, 0, 0> 1, <1, 3, 1> 2, <2, 1, 0> 3, <5, 0, 2> 4, <3, -1, 1> })
// "linear_spline -1, ..." is the type, then the time -1
#declare Neg = spline { linear_spline -1, <0, 0> 1, <2, 4> }
#debug concat("negative first time: ", vstr(2, Neg(0), ", ", 0, 4), "\n")
#declare Two = spline { cubic_spline 0, 1, 1, 3 }
#debug concat("two points, cubic: ", vstr(2, Two(0.2), ", ", 0, 4), "\n")
#debug concat("as natural_spline: ", vstr(2, Points(1.5, natural_spline), ", ", 0, 4), "\n")
camera { location <0, 0, -5> look_at 0 }
sphere { 0, 1 pigment { rgb 1 } }
