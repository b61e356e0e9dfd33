// #declare V = #include "File": the one value the included file gives, as
// POV-Ray 3.7 reads it (its mesh camera demos keep a mesh in a file this way).
// include_value.pov.err is the #debug output of povray 3.7.0.10 for this file
// (povray-debug: same).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare B = #include "include_value.inc"
#debug concat("max_extent: ", vstr(3, max_extent(B), ", ", 0, 1), "\n")
object { B pigment { rgb 1 } }
