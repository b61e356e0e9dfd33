// Conditionals, loops, #switch and #undef: directives.pov.err is the #debug
// output of povray 3.7.0.10 for this file (povray-debug: same).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare N = 3;
#if (N < 2) #debug "if: small\n" #elseif (N < 5) #debug "if: medium\n" #else #debug "if: large\n" #end
#if (0) #debug "never\n" #end
#if (N = 3 & !(N > 3)) #debug "if: and, not\n" #end
#ifdef (N) #debug "ifdef: N\n" #end
#ifndef (M) #debug "ifndef: M\n" #end
#undef N
#ifdef (N) #debug "still N\n" #else #debug "undef: N is gone\n" #end
// #while, and #break out of it
#declare I = 0;
#while (I < 10)
  #if (I = 4) #break #end
  #declare I = I + 1;
#end
#debug concat("while: I = ", str(I, 0, 0), "\n")
// #for: the variable after the loop is the first value past the end; a step
// that adds up to a little more than the end still counts (POV-Ray's epsilon)
#for (J, 1, 3) #debug str(J, 0, 0) #end
#debug concat(" after: ", str(J, 0, 0), "\n")
#for (J, 3, 1, -1) #debug str(J, 0, 0) #end
#debug "\n"
#declare K = 0;
#for (J, 0, 0.3, 0.1) #declare K = K + 1; #end
#debug concat("for 0 to 0.3 by 0.1: ", str(K, 0, 0), " passes\n")
#for (J, 5, 1) #debug "never\n" #end
// nested loops
#declare S = 0;
#for (A, 1, 3)
  #for (B, 1, A) #declare S = S + B; #end
#end
#debug concat("nested: ", str(S, 0, 0), "\n")
// #switch runs on through the next clauses up to #break, #else included
#macro Which(V)
  #switch (V)
    #case (1) #debug "one "
    #case (2) #debug "two "
    #break
    #range (3, 5) #debug "three to five "
    #else #debug "else "
  #end
  #debug "\n"
#end
Which(1)
Which(2)
Which(4.5)
Which(9)
#debug concat("version ", str(version, 0, 2), "\n")
#version 3.5;
#debug concat("version ", str(version, 0, 2), "\n")
#version 3.7;
// 'file' is no keyword of POV-Ray's, so scenes use it as a name (eclat's mesh
// file is a word only right inside a mesh)
#declare file = 2;
#debug concat("file = ", str(file + 1, 0, 0), "\n")
camera { location <0, 0, -5> look_at 0 }
sphere { 0, 1 pigment { rgb 1 } }
