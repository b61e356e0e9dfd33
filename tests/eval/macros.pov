// Macros and scopes: macros.pov.err is the #debug output of povray 3.7.0.10
// for this file (povray-debug: same).
#version 3.7;
global_settings { assumed_gamma 1 }
#macro Square(X) (X * X) #end
#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end
#macro Fib(N) #if (N < 2) N #else Fib(N - 1) + Fib(N - 2) #end #end
#debug concat("square ", str(Square(1 + 2), 0, 0), " fact ", str(Fact(6), 0, 0),
              " fib ", str(Fib(10), 0, 0), "\n")
// a macro's locals are its own; #declare of a new name is global
#declare Outer = 1;
#macro Locals()
  #local Outer = 2;
  #local Inner = 3;
  #declare Made = Outer + Inner;
#end
Locals()
#ifdef (Inner) #debug "Inner leaked\n" #end
#debug concat("outer ", str(Outer, 0, 0), " made ", str(Made, 0, 0), "\n")
// an identifier argument is passed by reference
#macro Bump(V) #declare V = V + 1; #end
#declare Count = 5;
Bump(Count)
Bump(Count)
#debug concat("count ", str(Count, 0, 0), "\n")
// a value argument is not
#macro Try(V) #local V = 100; #end
Try(Count + 0)
#debug concat("count ", str(Count, 0, 0), "\n")
// dynamic scope: a macro sees the locals of its caller
#macro Inside() #debug concat("sees ", str(CallerLocal, 0, 0), "\n") #end
#macro Caller() #local CallerLocal = 7; Inside() #end
Caller()
// include files have their own #local scope
#include "scope.inc"
#ifdef (Hidden) #debug "Hidden leaked\n" #end
#debug concat("shown ", str(Shown, 0, 0), " outer ", str(Outer, 0, 0), " from include ",
              str(FromInclude(4), 0, 0), "\n")
// a macro that gives a vector, used inside a vector expression
#macro Mid(A, B) ((A + B) / 2) #end
#declare V = Mid(<0, 0, 0>, <2, 4, 6>) + x;
#debug concat("mid ", vstr(3, V, ", ", 0, 1), "\n")
// (#if ...) in parentheses gives a value
#macro Sign(X) (#if (X < 0) -1 #elseif (X = 0) 0 #else #local One = 1; One #end) #end
#debug concat("signs ", str(Sign(-3), 0, 0), str(Sign(0), 0, 0), str(Sign(8), 0, 0), "\n")
camera { location <0, 0, -5> look_at 0 }
sphere { 0, 1 pigment { rgb 1 } }
