// Expressions, functions, strings, colours and arrays: expressions.pov.err is
// the #debug output of povray 3.7.0.10 for this file (povray-debug: same).
#version 3.7;
global_settings { assumed_gamma 1 }
#macro F(X) str(X, 0, 4) #end
#macro Show(Name, X) #debug concat(Name, " ", str(X, 0, 4), "\n") #end
#macro ShowV(Name, N, V) #debug concat(Name, " ", vstr(N, V, ", ", 0, 4), "\n") #end
// precedence: unary minus, then * /, then + -; comparisons and logic in parentheses
Show("arith", 1 + 2 * 3 - 4 / 2)
Show("unary", -2 * -3 + -(1 - 4))
Show("compare", (1 < 2) + (2 <= 2) + (3 = 3.00000000001) + (1 != 2) + (2 >= 3) + (2 > 1))
Show("logic", (1 & 0) + (1 | 0) * 2 + (!0) * 4 + (!5) * 8)
Show("chain", (3 > 2 > 1))
Show("cond", (1 < 2 ? 10 : 20) + (0 ? 1 : 2 ? 100 : 200))
ShowV("vector", 3, <1, 2, 3> * 2 + x - <0, 1>)
ShowV("compare vectors", 3, (<1, 2, 3> < <2, 2, 2>))
#declare Grey = rgb <0.2, 0.4, 0.6>;
Show("members", <1, 2, 3>.y + <1, 2, 3, 4>.t + Grey.gray + <5, 6>.u + Grey.blue)
// math
Show("abs", abs(-2.5)) Show("ceil", ceil(1.2)) Show("floor", floor(-1.2)) Show("int", int(-2.7))
Show("div", div(7, 2)) Show("mod", mod(-7, 2)) Show("pow", pow(2, 10)) Show("sqrt", sqrt(2))
Show("exp", exp(1)) Show("ln", ln(10)) Show("log", log(1000))
Show("sin", sin(pi / 6)) Show("cos", cos(pi)) Show("tan", tan(pi / 4))
Show("asin", asin(1)) Show("acos", acos(0)) Show("atan", atan(1)) Show("atan2", atan2(1, -1))
Show("sinh", sinh(1)) Show("cosh", cosh(1)) Show("tanh", tanh(1))
Show("asinh", asinh(1)) Show("acosh", acosh(2)) Show("atanh", atanh(0.5))
Show("degrees", degrees(pi / 2)) Show("radians", radians(180))
Show("max", max(1, 5, 3)) Show("min", min(4, 2, 3))
Show("select", select(-1, 1, 2) + 10 * select(0, 1, 2, 3) + 100 * select(1, 1, 2, 3))
Show("bitwise", bitwise_and(12, 10) + 100 * bitwise_or(12, 10) + 10000 * bitwise_xor(12, 10))
// vectors
ShowV("vcross", 3, vcross(x, y))
Show("vdot", vdot(<1, 2, 3>, <4, 5, 6>))
Show("vlength", vlength(<3, 4, 12>))
ShowV("vnormalize", 3, vnormalize(<3, 0, 4>))
ShowV("vrotate", 3, vrotate(<1, 2, 3>, <30, 45, 60>))
ShowV("vaxis_rotate", 3, vaxis_rotate(<1, 2, 3>, <1, 1, 0>, 60))
// strings
#debug concat("[", str(3.14159, 8, 2), "][", str(3.14159, -8, 2), "][", str(2.5, 0, 0), "][",
              str(1/3, 0, -1), "]\n")
#debug concat("[", vstr(2, <1, 2, 3>, "|", -4, 1), "][", substr("Hello World", 7, 5), "][",
              strupr("aBc"), strlwr("aBc"), "][", chr(65), "]\n")
Show("strings", strlen("hello") + 10 * asc("A") + 1000 * strcmp("abc", "abd") + val("2.5e1"))
Show("string compare", ("abc" < "abd") + 2 * ("b" = "b") + 4 * ("a" > "b"))
Show("file_exists", file_exists("expressions.pov") + 2 * file_exists("no such file"))
// colours
#declare C1 = color red 1 green 0.5;
#declare C2 = rgb <1, 0.5, 0> filter 0.25 transmit 0.5;
#declare C3 = rgbt <0.1, 0.2, 0.3, 0.4>;
#declare C4 = color 0.5;
#declare C5 = srgb <0.5, 0.2, 1>;
#declare C6 = srgbft <0.04, 0.5, 0.9, 0.1, 0.2>;
#declare C7 = rgb 1 * 0.5 + 0.1;
#declare C8 = C2 * 2 + C3;
ShowV("color", 5, C1) ShowV("filter", 5, C2) ShowV("rgbt", 5, C3) ShowV("color float", 5, C4)
ShowV("srgb", 5, C5) ShowV("srgbft", 5, C6) ShowV("colour sum", 5, C7) ShowV("colour arithmetic", 5, C8)
// arrays
#declare A = array[2][3] { { 1, 2, 3 }, { 4, 5, 6 } }
#declare A[1][2] = A[0][0] + A[1][1];
Show("array", A[1][2] + 10 * dimensions(A) + 100 * dimension_size(A, 2))
#declare B = array[3]
#declare B[1] = 7;
Show("defined", defined(B[1]) + 2 * defined(B[0]) + 4 * defined(Nothing))
camera { location <0, 0, -5> look_at 0 }
sphere { 0, 1 pigment { rgb 1 } }
