// #fopen, #read and #fclose: fileio.data is what POV-Ray's #write wrote (see
// tests/lang.test, which checks that eclat writes the same); fileio.pov.err is
// the #debug output of povray 3.7.0.10 for this file (povray-debug: same).
#version 3.7;
global_settings { assumed_gamma 1 }
#fopen F "fileio.data" read
#read (F, S, A, V)
#debug concat(S, " ", str(A, 0, 3), " ", vstr(3, V, ",", 0, 3), "\n")
#fclose F
#ifdef (F) #debug "F is still defined\n" #else #debug "#fclose undefines F\n" #end
// the end of the file closes it: the handle is undefined after the last value
#fopen F "fileio.data" read
#declare N = 0;
#while (defined(F))
  #ifdef (Item) #undef Item #end  // POV-Ray reads no float into a vector
  #read (F, Item)
  #declare N = N + 1;
#end
#debug concat("values: ", str(N, 0, 0), ", the last: ", Item, "\n")
#fclose F
camera { location <0, 0, -5> look_at 0 }
sphere { 0, 1 pigment { rgb 1 } }
