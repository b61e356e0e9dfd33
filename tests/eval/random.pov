// seed() and rand() reproduce POV-Ray 3.7's generator: random.pov.err is the
// #debug output of povray 3.7.0.10 for this file (povray-debug: same).
#version 3.7;
global_settings { assumed_gamma 1 }
#macro Draw(S, N)
  #local I = 0;
  #while (I < N)
    #debug concat(str(rand(S), 0, 10), " ")
    #local I = I + 1;
  #end
  #debug "\n"
#end
#declare A = seed(0);
Draw(A, 6)
#declare B = seed(12345);
Draw(B, 3)
#declare C = seed(-7);
Draw(C, 3)
#declare D = seed(3.9);        // the seed is truncated to an integer
Draw(D, 3)
#declare E = seed(4294967295); // out of the range of an int: as x86 converts it
Draw(E, 2)
// two streams from the same seed are independent
#declare F = seed(1);
#declare G = seed(1);
#debug concat(str(rand(F), 0, 10), " ", str(rand(G), 0, 10), " ", str(rand(F), 0, 10), "\n")
#debug concat("streams ", str(A, 0, 0), " ", str(G, 0, 0), "\n")
camera { location <0, 0, -5> look_at 0 }
sphere { 0, 1 pigment { rgb rand(A) } }
