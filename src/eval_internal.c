/* eval_internal.c: POV-Ray's internal functions (functions.inc's
 * "function { internal(N) }"), written here in POV-Ray's own function
 * language from their definitions in POV-Ray 3.7 (source/vm/fnintern.cpp),
 * so that the device runs them like any function the scene declares: the
 * text is parsed once when a scene first calls one and becomes a program of
 * scene.functions (eval_function.c).
 *
 * A new one is a line of the table: its number, and its text, whose
 * parameters are x, y, z and then P0, P1... as functions.inc lists them.
 * Those the language cannot write, which loop as often as a parameter says or
 * read the noise, are one op each instead (op_internals, at the end). All of
 * POV-Ray 3.7's are here but internal(77), f_pattern, which functions.inc
 * does not declare (a pattern function is its own op, FOP_PATTERN). */
#include <stdio.h>
#include <string.h>

#include "eval_int.h"
#include "parse.h"

/* min(10, max(P0 * r, -10)): the "field strength" clamp many of them share. */
#define FIELD(r) "min(10, max(P0 * (" r "), -10))"

/* x*x, y*y, z*z kept as one product each: POV-Ray squares once and reuses
 * the square, and a*a*b rounds differently from (a*a)*b. */
#define X2 "(x*x)"
#define Y2 "(y*y)"
#define Z2 "(z*z)"
#define SQ(a) "((" a ") * (" a "))"

/* x, nudged off 0 where x and z both are (atan2's argument), as POV-Ray does
 * before an angle about y. */
#define NUDGED_X(eps) "select(-(abs(x) + abs(z)), x, " eps ")"

/* v + 2 pi when v < 0: fmod's result turned into [0, 2 pi). */
#define POSITIVE_ANGLE(v) "(" v " + select(" v ", 2 * pi, 0))"

/* f_helix1's pieces (fnintern.cpp names them as it reassigns x and z): the
 * angle about y, wound by the helices, in [0, 2 pi) (the origin's x nudged,
 * as POV-Ray does); the point's z along the helix and x off its centre line;
 * both turned by P6 degrees (no turn when P6 is 0: cos 1, sin 0); the cross
 * section's radius for P5 1 (a circle), 0 (a square) or another exponent. */
#define HELIX_TH1 "mod(atan2(z, " NUDGED_X("0.000001") ") * P0 + y * P1 * P0, 2 * pi)"
#define HELIX_TH POSITIVE_ANGLE(HELIX_TH1)
#define HELIX_Z "((" HELIX_TH " - pi) / P4 / (P1 * P0))"
#define HELIX_X "(sqrt(x*x + z*z) - P3)"
#define HELIX_XR "(" HELIX_X " * cos(radians(P6)) - " HELIX_Z " * sin(radians(P6)))"
#define HELIX_ZR "(" HELIX_X " * sin(radians(P6)) + " HELIX_Z " * cos(radians(P6)))"
#define HELIX_R2 "(P5 = 1 ? sqrt(" HELIX_X " * " HELIX_X " + " HELIX_Z " * " HELIX_Z ") : (P5 != 0 ?" \
	" pow(pow(abs(" HELIX_XR "), 2 / P5) + pow(abs(" HELIX_ZR "), 2 / P5), P5 * 0.5) :" \
	" max(abs(" HELIX_XR "), abs(" HELIX_ZR "))))"

/* The "SOR switch" (ROT2D in fnintern.cpp) of the algebraic cylinders and the
 * _2d curves: when parameter S is above 0, the curve drawn in the x-y plane is
 * revolved about y (its x is the distance from the y axis less D) and turned by
 * A degrees in its plane; otherwise x and y are the point's. Every use of x and
 * y in those functions reads SOR_X and SOR_Y (an angle of 0 turns exactly). */
#define SOR_D(D) "(sqrt(x*x + z*z) - " D ")"
#define SOR_X(S, D, A) "(" S " > 0 ? " SOR_D(D) " * cos(radians(" A ")) - y * sin(radians(" A ")) : x)"
#define SOR_Y(S, D, A) "(" S " > 0 ? " SOR_D(D) " * sin(radians(" A ")) + y * cos(radians(" A ")) : y)"
/* the three places the switch takes in the parameter lists */
#define CX SOR_X("P2", "P3", "P4")
#define CY SOR_Y("P2", "P3", "P4")
#define C2X SOR_X("P3", "P4", "P5")
#define C2Y SOR_Y("P3", "P4", "P5")
#define C3X SOR_X("P4", "P5", "P6")
#define C3Y SOR_Y("P4", "P5", "P6")
/* the algebraic cylinders' clamp to [-P1, P1] */
#define CYL_FIELD(r) "min(P1, max(P0 * (" r "), -P1))"

/* f_helical_torus's pieces: the distance from the y axis, the angle about y
 * (x nudged), the angle about the tube's centre circle, the distance from that
 * circle, and the winding angle in [0, 2 pi). */
#define HT_R0 "sqrt(x*x + z*z)"
#define HT_PH "atan2(" NUDGED_X("0.000001") ", z)"
#define HT_TUBE "atan2(" HT_R0 " - P0, y)"
#define HT_R "sqrt((" HT_R0 " - P0) * (" HT_R0 " - P0) + y*y)"
#define HT_TH1 "mod(" HT_PH " * P1 + " HT_TUBE " * P2, 2 * pi)"
#define HT_TH POSITIVE_ANGLE(HT_TH1)

/* f_helix2's point in the frame of the helix at its height: the centre
 * circle's point (cos, sin of y * P1 times P3) subtracted, then turned by that
 * angle; and the cross section's radius for P5 1 (a circle), 0 (a square) or
 * another exponent. */
#define H2_DX "(x - P3 * cos(y * P1))"
#define H2_DZ "(z - P3 * sin(y * P1))"
#define H2_X "(" H2_DX " * cos(y * P1) + " H2_DZ " * sin(y * P1))"
#define H2_Z "(-" H2_DX " * sin(y * P1) + " H2_DZ " * cos(y * P1))"
#define H2_R "(P5 = 1 ? sqrt(" H2_X " * " H2_X " + " H2_Z " * " H2_Z ") : (P5 != 0 ?" \
	" pow(pow(abs(" H2_X "), 2 / P5) + pow(abs(" H2_Z "), 2 / P5), P5 * 0.5) : max(abs(" H2_X "), abs(" H2_Z "))))"

/* f_hex_x and f_hex_y: the point folded into one cell of the hexagonal
 * lattice (x1, y1 from the nearer of its two centres), and whether it lies in
 * the first 30 degrees of it. */
#define HEX_X1 "abs(mod(abs(x), sqrt(3)) - sqrt(3) / 2)"
#define HEX_Y1 "abs(mod(abs(y), 3) - 1.5)"
#define HEX_FAR "(" HEX_X1 " * " HEX_X1 " + " HEX_Y1 " * " HEX_Y1 " > (sqrt(3) / 2 - " HEX_X1 ") * (sqrt(3) / 2 - " \
	HEX_X1 ") + (1.5 - " HEX_Y1 ") * (1.5 - " HEX_Y1 "))"
#define HEX_X "(" HEX_FAR " ? sqrt(3) / 2 - " HEX_X1 " : " HEX_X1 ")"
#define HEX_Y "(" HEX_FAR " ? 1.5 - " HEX_Y1 " : " HEX_Y1 ")"
#define HEX_LOW "(atan2(" HEX_Y ", " HEX_X ") < pi / 6)"

/* f_mesh1's four families of threads: v mod 2m in [0, 2m), then one thread's
 * distance (negated) from the point, its height y moved by WAVE (a cosine). */
#define MESH_MOD(v, m) "(mod(" v ", " m " * 2) + select(mod(" v ", " m " * 2), " m " * 2, 0))"
#define MESH_ARM(v, m, wave) "-sqrt(" SQ("(y " wave ") * P4") " + " SQ("abs(" MESH_MOD(v, m) " - " m ") * P2") ")"

/* f_quantum's radius (x nudged as POV-Ray does), cos of the polar angle, and
 * twice the distance from the origin. */
#define QU_R "sqrt(" NUDGED_X("1e-6") " * " NUDGED_X("1e-6") " + z*z)"
#define QU_TH "cos(atan2(" QU_R ", y))"
#define QU_R2 "(sqrt(" QU_R " * " QU_R " + y*y) * 2)"
#define QU_T "(" QU_R2 " * " QU_R2 " * exp(-" QU_R2 " * 0.33333333) * (3 * " QU_TH " * " QU_TH " - 1))"

/* f_spiral's distance across the arms of the spiral and its cross section's
 * radius (P5 as f_helix1's). */
#define SP_R2 "(mod(sqrt(x*x + z*z) + P0 * atan2(z, " NUDGED_X("0.000001") ") / (2 * pi), P0) - P0 * 0.5)"
#define SP_CROSS "(P5 = 1 ? sqrt(" SP_R2 " * " SP_R2 " + y*y) : (P5 != 0 ? pow(pow(abs(" SP_R2 "), 2 / P5)" \
	" + pow(abs(y), 2 / P5), 1 / (2 / P5)) : max(abs(" SP_R2 "), abs(y))))"

/* f_dupin_cyclid's constants of its parameters */
#define DC_P1 "(P2*P2 - P4*P4 - (P3 + P1) * (P3 + P1))"
#define DC_P2 "(P2*P2 - P4*P4 - (P3 - P1) * (P3 - P1))"
#define DC_R2 "(P5*P5)"

/* f_enneper's z, kept off 0 */
#define EN_Z "(abs(z) < 0.2 ? 0.2 : z)"

static const struct {
	int number;
	const char *text;
} internals[] = {
	{ 0, "function(x, y, z, P0, P1, P2, P3, P4) { -" CYL_FIELD("-(" SQ(CX) " * abs(" CX ") - " SQ(CX) " + " SQ(CY) ")")
	     " }" },   /* f_algbr_cyl1 */
	{ 1, "function(x, y, z, P0, P1, P2, P3, P4) { " CYL_FIELD("-(2 * " SQ(CX) " * " SQ(CX) " - 3 * " SQ(CX) " * " CY
	     " + " SQ(CY) " - 2 * " SQ(CY) " * " CY " + " SQ(CY) " * " SQ(CY) ")") " }" },   /* f_algbr_cyl2 */
	{ 2, "function(x, y, z, P0, P1, P2, P3, P4) { " CYL_FIELD("-(" SQ(CX) " * " SQ(CX) " + " SQ(CX) " * " SQ(CY)
	     " - 2 * " SQ(CX) " * " CY " - " CX " * " SQ(CY) " + " SQ(CY) ")") " }" },   /* f_algbr_cyl3 */
	{ 3, "function(x, y, z, P0, P1, P2, P3, P4) { " CYL_FIELD("-(" SQ(CX) " * " SQ(CX) " + " SQ(CY) " * " SQ(CY)
	     " + 2 * " SQ(CX) " * " SQ(CY) " + 3 * " SQ(CX) " * " CY " - " SQ(CY) " * " CY ")") " }" },   /* f_algbr_cyl4 */
	{ 4, "function(x, y, z, P0, P1) { " FIELD(Y2 " * (P1*P1 - (" X2 " + " Z2 ")) - "
	     SQ(X2 " + " Z2 " + 2 * P1 * y - P1*P1")) " }" },   /* f_bicorn */
	{ 5, "function(x, y, z, P0, P1) { " FIELD("-(" SQ(X2 " + y*y + " Z2) " - P1 * (" X2 " + " Z2 ") * y)") " }" },
	                                                                                      /* f_bifolia */
	{ 6, "function(x, y, z, P0, P1, P2, P3, P4) { -(P1 * (1 - min(((x + P0*0.5) * (x + P0*0.5) + " Y2 " + " Z2
	     ") * P2 * P2, 1)) * (1 - min(((x + P0*0.5) * (x + P0*0.5) + " Y2 " + " Z2 ") * P2 * P2, 1))"
	     " + P3 * (1 - min(((x - P0*0.5) * (x - P0*0.5) + " Y2 " + " Z2 ") * P4 * P4, 1))"
	     " * (1 - min(((x - P0*0.5) * (x - P0*0.5) + " Y2 " + " Z2 ") * P4 * P4, 1))) }" },   /* f_blob */
	{ 7, "function(x, y, z, P0, P1, P2, P3) { P3 - (exp(-(" X2 " + " Y2 " + " Z2 ") * P1)"
	     " + exp(-((x - P0) * (x - P0) + " Y2 " + " Z2 ") * P1)) * P2 }" },   /* f_blob2 */
	{ 8, "function(x, y, z, P0, P1) { " FIELD("P1 * (64 * (1 - z) * (1 - z) * (1 - z) * " Z2 " * z"
	     " - 48 * (1 - z) * (1 - z) * " Z2 " * (3 * " X2 " + 3 * " Y2 " + 2 * " Z2 ")"
	     " + 12 * (1 - z) * z * (27 * (" X2 " + " Y2 ") * (" X2 " + " Y2 ") - 24 * " Z2 " * (" X2 " + " Y2 ")"
	     " + 36 * sqrt(2) * y * z * (" Y2 " - 3 * " X2 ") + 4 * " Z2 " * " Z2 ")"
	     " + (9 * " X2 " + 9 * " Y2 " - 2 * " Z2 ") * (-81 * (" X2 " + " Y2 ") * (" X2 " + " Y2 ")"
	     " - 72 * " Z2 " * (" X2 " + " Y2 ") + 108 * sqrt(2) * x * z * (" X2 " - 3 * " Y2 ") + 4 * " Z2 " * " Z2 "))")
	     " }" },   /* f_boy_surface */
	{ 9, "function(x, y, z, P0) { -max(min(z, cos(atan2(z, " NUDGED_X("0.0001") ") * 0.5) * P0 * 0.5"
	     " - sqrt(" SQ("sqrt(" SQ(NUDGED_X("0.0001") " + P0 * 0.25") " + z*z) - P0 * 0.75") " + y*y)),"
	     " P0 * 0.5 - sqrt(" SQ(NUDGED_X("0.0001") " - P0 * 0.5") " + z*z + y*y)) }" },   /* f_comma */
	{ 10, "function(x, y, z, P0, P1, P2, P3) { P3 - P2 * max(exp(-(x*x*P0 + y*y*P0 + z*z) * P1),"
	      " exp(-(x*x*P0 + y*y + z*z*P0) * P1), exp(-(x*x + y*y*P0 + z*z*P0) * P1)) }" },   /* f_cross_ellipsoids */
	{ 11, "function(x, y, z, P0) { " FIELD("x*x*z*z - y") " }" },   /* f_crossed_trough */
	{ 12, "function(x, y, z, P0) { " FIELD("-(x*x*x - y*y*y - z)") " }" },   /* f_cubic_saddle */
	{ 13, "function(x, y, z, P0) { " FIELD(Z2 "*" X2 " - " Z2 "*" Z2 " - 2*z*" X2 " + 2*" Z2 "*z + " X2 " - " Z2
	      " - (" X2 " - z) * (" X2 " - z) - " Y2 "*" Y2 " - 2*" X2 "*" Y2 " - " Y2 "*" Z2 " + 2*" Y2 "*z + " Y2) " }" },
	                                                                                      /* f_cushion */
	{ 14, "function(x, y, z, P0) { " FIELD("-(" X2 "*" X2 " + 2*" X2 "*" Z2 " - 0.36*" X2 " - " Y2 "*" Y2
	      " + 0.25*" Y2 " + " Z2 "*" Z2 ")") " }" },   /* f_devils_curve */
	{ 15, "function(x, y, z, P0, P1, P2, P3, P4, P5) { " FIELD("-(" SQ(C2X) " * (" SQ(C2X) " - P1*P1) - " SQ(C2Y)
	      " * (" SQ(C2Y) " - P2*P2))") " }" },   /* f_devils_curve_2d */
	{ 16, "function(x, y, z, P0, P1, P2, P3, P4, P5) { " FIELD("-(" DC_P1 " * " DC_P2 " * (" X2 "*" X2 " + " Y2 "*" Y2
	      " + " Z2 "*" Z2 ") + 2 * (" DC_P1 " * " DC_P2 " * (" X2 "*" Y2 " + " X2 "*" Z2 " + " Y2 "*" Z2 "))"
	      " + 2 * " DC_R2 " * ((-P4*P4 - P3*P3 + P2*P2 + P1*P1) * (2*x*P3 + 2*y*P4 - " DC_R2 ") - 4*P4*P2*P2*y)"
	      " * (" X2 " + " Y2 " + " Z2 ") + 4 * " DC_R2 " * " DC_R2 " * (P3*x + P4*y) * (-" DC_R2 " + P4*y + P3*x)"
	      " + 4 * " DC_R2 " * " DC_R2 " * P1*P1 * " Y2 " + " DC_R2 " * " DC_R2 " * " DC_R2 " * " DC_R2 ")") " }" },
	                                                                                      /* f_dupin_cyclid */
	{ 17, "function(x, y, z, P0, P1, P2) { sqrt(x*x*P0*P0 + y*y*P1*P1 + z*z*P2*P2) }" },   /* f_ellipsoid */
	/* f_enneper: POV-Ray writes its constants as integer divisions (2/3,
	 * 1/4, 8/9, 2/9 in C), all 0, which leaves these terms */
	{ 18, "function(x, y, z, P0) { " FIELD("-(" SQ("(" Y2 " - " X2 ") / (2 * " EN_Z ") + 2 * " Z2 " / 9") " * ((" Y2
	      " - " X2 ") / (2 * " EN_Z ") + 2 * " Z2 " / 9) - 6 * " SQ("(" Y2 " - " X2 ") / (4 * " EN_Z ")") ")") " }" },
	{ 19, "function(x, y, z, P0, P1, P2, P3) { P3 - P2 * (exp(-(x*x*P0 + y*y*P0 + z*z) * P1)"
	      " + exp(-(x*x*P0 + y*y + z*z*P0) * P1) + exp(-(x*x + y*y*P0 + z*z*P0) * P1)) }" },   /* f_flange_cover */
	{ 20, "function(x, y, z, P0, P1, P2) { " FIELD("(" Y2 " + " Z2 ") * (1 + (P2 - 4*P1) * x) + " X2 " * (1 + P2)")
	      " }" },   /* f_folium_surface */
	{ 21, "function(x, y, z, P0, P1, P2, P3, P4, P5) { " FIELD("-(" SQ(C2Y) " * (1 + (P2 - 4*P1) * " C2X ") + "
	      SQ(C2X) " * (1 + P2))") " }" },   /* f_folium_surface_2d */
	{ 22, "function(x, y, z, P0) { " FIELD("0.5*" X2 "*" X2 "*x + 0.5*" X2 "*" X2 " - (y*y + z*z)") " }" },   /* f_glob */
	{ 23, "function(x, y, z, P0) { " FIELD("-(pow(2*x*x + y*y + z*z - 1, 3) - 0.1*x*x*z*z*z - y*y*z*z*z)") " }" },
	                                                                                      /* f_heart */
	{ 24, "function(x, y, z, P0, P1, P2, P3, P4, P5, P6, P7, P8, P9) { -max(P4 + P5 - P0 - " HT_R0 ","
	      " cos(atan2((" HT_TH " - pi) * P8, " HT_R " - P5) * P7 + " HT_PH " * P9) * P3 + P4"
	      " - min(sqrt((" HT_R " - P5) * (" HT_R " - P5) + (" HT_TH " - pi) * (" HT_TH " - pi) * P6), " HT_R " + P5)) }" },
	                                                                                      /* f_helical_torus */
	{ 25, "function(x, y, z, P0, P1, P2, P3, P4, P5, P6) { -P2 + min(P3 + sqrt(x*x + z*z), " HELIX_R2 ") }" },
	                                                                                      /* f_helix1 */
	{ 26, "function(x, y, z, P0, P1, P2, P3, P4, P5, P6) { " H2_R " - P2 }" },   /* f_helix2 */
	{ 27, "function(x, y, z, P0) { (" HEX_LOW " ? " HEX_X " : cos(pi / 3) * " HEX_X " + sin(pi / 3) * " HEX_Y ") }" },
	                                                                                      /* f_hex_x */
	{ 28, "function(x, y, z, P0) { (" HEX_LOW " ? " HEX_Y " : abs(-sin(pi / 3) * " HEX_X " + cos(pi / 3) * " HEX_Y "))"
	      " }" },
	                                                                                      /* f_hex_y */
	{ 30, "function(x, y, z, P0) { " FIELD("-(4 * (" X2 " + " Y2 " + " Z2 " - 13) * (" X2 " + " Y2 " + " Z2 " - 13)"
	      " * (" X2 " + " Y2 " + " Z2 " - 13) + 27 * (3*" X2 " + " Y2 " - 4*" Z2 " - 12) * (3*" X2 " + " Y2 " - 4*" Z2
	      " - 12))") " }" },   /* f_hunt_surface */
	{ 31, "function(x, y, z, P0, P1, P2) { " FIELD("-(" X2 "*" X2 " + 2*" X2 "*" Y2 " - 2*" X2 "*" Z2
	      " - 2*(P1*P1 + P2*P2)*" X2 " + " Y2 "*" Y2 " - 2*" Y2 "*" Z2 " + 2*(P1*P1 - P2*P2)*" Y2 " + " Z2 "*" Z2
	      " + 2*(P1*P1 + P2*P2)*" Z2 " + (P1*P1 - P2*P2) * (P1*P1 - P2*P2))") " }" },   /* f_hyperbolic_torus */
	{ 32, "function(x, y, z, P0, P1, P2, P3) { P3 - P2 * min(exp(-(x*x*P0 + y*y*P0 + z*z) * P1),"
	      " exp(-(x*x*P0 + y*y + z*z*P0) * P1), exp(-(x*x + y*y*P0 + z*z*P0) * P1)) }" },   /* f_isect_ellipsoids */
	{ 33, "function(x, y, z, P0, P1, P2) { " FIELD("-((y*y + z*z) - P2*P2 * " X2 "*" X2 " + P2*P2 * P1*P1 * " X2 ")")
	      " }" },   /* f_kampyle_of_eudoxus */
	/* f_kampyle_of_eudoxus_2d: P1*P2 where the 3d one has P1*P1, as in POV-Ray */
	{ 34, "function(x, y, z, P0, P1, P2, P3, P4, P5) { " FIELD("-(" SQ(C2Y) " - P2*P2 * " SQ(C2X) " * " SQ(C2X)
	      " + P2*P2 * P1*P2 * " SQ(C2X) ")") " }" },
	{ 35, "function(x, y, z, P0) { " FIELD("-((" X2 " + " Y2 " + " Z2 " + 2*y - 1) * ((" X2 " + " Y2 " + " Z2
	      " - 2*y - 1) * (" X2 " + " Y2 " + " Z2 " - 2*y - 1) - 8*" Z2 ") + 16*x*z*(" X2 " + " Y2 " + " Z2 " - 2*y - 1))")
	      " }" },   /* f_klein_bottle */
	{ 36, "function(x, y, z, P0) { " FIELD("-(" X2 "*" X2 " + " Y2 "*" Y2 " + " Z2 "*" Z2 " - " X2 " - " Y2 " - " Z2
	      " - " X2 "*" Y2 " - " X2 "*" Z2 " - " Y2 "*" Z2 " + 1)") " }" },   /* f_kummer_surface_v1 */
	{ 37, "function(x, y, z, P0, P1, P2, P3) { " FIELD("-(" X2 "*" X2 " + " Y2 "*" Y2 " + " Z2 "*" Z2 " + P1 * (" X2
	      " + " Y2 " + " Z2 ") + P2 * (" X2 "*" Y2 " + " X2 "*" Z2 " + " Y2 "*" Z2 ") + P3*x*y*z - 1)") " }" },
	                                                                                      /* f_kummer_surface_v2 */
	{ 38, "function(x, y, z, P0) { " FIELD("-(" X2 "*" X2 " - " X2 " + " Y2 " + " Z2 ")") " }" },
	                                                                                      /* f_lemniscate_of_gerono */
	{ 39, "function(x, y, z, P0, P1, P2, P3, P4, P5) { " FIELD("-(" SQ(C2Y) " - P2*P2 * P1*P1 * " SQ(C2X) " + P2*P2 * "
	      SQ(C2X) " * " SQ(C2X) ")") " }" },   /* f_lemniscate_of_gerono_2d */
	{ 40, "function(x, y, z, P0, P1, P2, P3, P4) { -max(" MESH_ARM("z - P1", "P1", "- cos(x * (pi / P0)) * P3") ","
	      " max(" MESH_ARM("z", "P1", "+ cos(x * (pi / P0)) * P3") ", max(" MESH_ARM("x - P0", "P0",
	      "+ cos(z * (pi / P1)) * P3") ", " MESH_ARM("x", "P0", "- cos(z * (pi / P1)) * P3") "))) }" },   /* f_mesh1 */
	{ 41, "function(x, y, z, P0) { " FIELD("-(4*x*x*(x*x + y*y + z*z) - y*y*(1 - y*y - z*z))") " }" },   /* f_mitre */
	{ 42, "function(x, y, z, P0) { " FIELD("-(y*y*y + z*z*z - 6*y*z)") " }" },   /* f_nodal_cubic */
	{ 43, "function(x, y, z, P0) { " FIELD(Z2 "*" X2 " - " Z2 "*" Z2 " - 2*z*" X2 " + 2*" Z2 "*z + " X2 " - " Z2
	      " - (" X2 " - z) * (" X2 " - z) - " Y2 "*" Y2 " - 2*" Y2 "*" X2 " - " Y2 "*" Z2 " + 2*" Y2 "*z + " Y2) " }" },
	                                                                                      /* f_odd */
	{ 44, "function(x, y, z, P0, P1, P2, P3) { " FIELD("-(" SQ(X2 " + " Y2 " + " Z2 " + P1*P1") " - P3*P1*P1 * (" X2
	      " + " Z2 ") - P2*P2)") " }" },   /* f_ovals_of_cassini */
	{ 45, "function(x, y, z, P0) { " FIELD("-(x*x - y + z*z)") " }" },   /* f_paraboloid */
	{ 46, "function(x, y, z, P0, P1, P2) { " FIELD("-(" X2 "*" X2 " + 2*" X2 "*" Y2 " - 2*" X2 "*z - (P1*P1 + P2*P2)*"
	      X2 " + " Y2 "*" Y2 " - 2*" Y2 "*z + (P1*P1 - P2*P2)*" Y2 " + " Z2 " + (P1*P1 + P2*P2)*z"
	      " + (P1*P1 - P2*P2) * (P1*P1 - P2*P2))") " }" },   /* f_parabolic_torus */
	{ 47, "function { atan2(sqrt(x*x + z*z), y) }" },   /* f_ph */
	{ 48, "function(x, y, z, P0) { " FIELD(X2 "*" X2 " + " Y2 "*" Y2 " + " Z2 "*" Z2 " - (" X2 " + " Y2 " + " Z2 ")")
	      " }" },   /* f_pillow */
	{ 49, "function(x, y, z, P0) { -" FIELD("-((" X2 "*" X2 " - " X2 "*x) + y*y + z*z)") " }" },   /* f_piriform */
	{ 50, "function(x, y, z, P0, P1, P2, P3, P4, P5, P6) { " FIELD("-(" SQ(C3Y) " - P1 * P3*P3 * " SQ(C3X) " * " C3X
	      " - P2 * P3*P3 * " SQ(C3X) " * " SQ(C3X) ")") " }" },   /* f_piriform_2d */
	/* f_poly4: the radius below -5 counts as -5 */
	{ 51, "function(x, y, z, P0, P1, P2, P3, P4) { -((P0 + P1*y + P2*" Y2 " + P3*" Y2 "*y + P4*" Y2 "*" Y2 ") < -5 ? -5 :"
	      " P0 + P1*y + P2*" Y2 " + P3*" Y2 "*y + P4*" Y2 "*" Y2 ") + sqrt(x*x + z*z) }" },
	{ 53, "function(x, y, z, P0) { (" QU_T " * " QU_T " - 12) * -0.1 }" },   /* f_quantum */
	{ 54, "function(x, y, z, P0) { " FIELD("-(" X2 "*" X2 " + " Z2 "*" Z2 " - y)") " }" },   /* f_quartic_paraboloid */
	{ 55, "function(x, y, z, P0) { " FIELD("-(" X2 "*" X2 " - " Z2 "*" Z2 " - y)") " }" },   /* f_quartic_saddle */
	{ 56, "function(x, y, z, P0, P1, P2) { " FIELD("-((x*x + z*z) * y*y + P2*P2 * (x*x + z*z) - P2*P2 * P1*P1)")
	      " }" },   /* f_quartic_cylinder */
	{ 57, "function { sqrt(x*x + y*y + z*z) }" },   /* f_r */
	{ 60, "function(x, y, z, P0, P1, P2, P3) { -P0 + sqrt(pow(max(max(P0 - P1 - x, 0), max(x - (P1 - P0), 0)), 2)"
	      " + pow(max(max(P0 - P2 - y, 0), max(y - (P2 - P0), 0)), 2)"
	      " + pow(max(max(P0 - P3 - z, 0), max(z - (P3 - P0), 0)), 2)) - 1e-6 }" },   /* f_rounded_box */
	{ 61, "function(x, y, z, P0) { -P0 + sqrt(x*x + y*y + z*z) }" },   /* f_sphere */
	{ 62, "function(x, y, z, P0, P1, P2, P3, P4) { -(exp(-(" X2 " + " Y2 " + " Z2 ") * P3) * P4"
	      " - exp(-(" X2 "*P0 + " Y2 "*P0 + " Z2 ") * P1) - exp(-(" X2 "*P0 + " Y2 " + " Z2 "*P0) * P1)"
	      " - exp(-(" X2 " + " Y2 "*P0 + " Z2 "*P0) * P1)) * P2 }" },   /* f_spikes */
	{ 63, "function(x, y, z, P0, P1, P2, P3) { -(P0 * cos(P1*x) * cos(P2*z) * exp(-P3 * (x*x + z*z)) - y) }" },
	                                                                                      /* f_spikes_2d */
	{ 64, "function(x, y, z, P0, P1, P2, P3, P4, P5) { -min(P2 - sqrt(x*x + y*y + z*z), P1 - min(" SP_CROSS ","
	      " sqrt(x*x + y*y + z*z))) }" },   /* f_spiral */
	{ 65, "function(x, y, z, P0) { " FIELD("-(" X2 "*" Y2 " + " X2 "*" Z2 " + " Y2 "*" Z2 " + x*y*z)") " }" },
	                                                                                      /* f_steiners_roman */
	{ 66, "function(x, y, z, P0, P1, P2, P3) { " FIELD("-((P2 - x) * (y*y + z*z) - P3*P3 * P1 * " X2 " - P3*P3 * " X2
	      " * x)") " }" },   /* f_strophoid */
	{ 67, "function(x, y, z, P0, P1, P2, P3, P4, P5, P6) { " FIELD("-((P2 - " C3X ") * " SQ(C3Y) " - P3*P3 * P1 * "
	      SQ(C3X) " - P3*P3 * " SQ(C3X) " * " C3X ")") " }" },   /* f_strophoid_2d */
	{ 68, "function(x, y, z, P0, P1) { 1 - pow(pow(pow(abs(x), 2 / P0) + pow(abs(y), 2 / P0), P0 / P1)"
	      " + pow(abs(z), 2 / P1), P1 * 0.5) }" },   /* f_superellipsoid */
	{ 69, "function { atan2(x, z) }" },   /* f_th */
	{ 70, "function(x, y, z, P0, P1) { -P1 + sqrt(pow(sqrt(x*x + z*z) - P0, 2) + y*y) }" },   /* f_torus */
	{ 71, "function(x, y, z, P0, P1, P2) { " FIELD("-(pow(x*x + y*y + z*z, 2) - 2*(P1*P1 + P2*P2)*x*x"
	      " + 2*(P1*P1 - P2*P2)*y*y - 2*(P1*P1 + P2*P2)*z*z + pow(P1*P1 - P2*P2, 2))") " }" },   /* f_torus2 */
	{ 72, "function(x, y, z, P0) { " FIELD("-(4 * (" X2 "*" X2 " + (" Y2 " + " Z2 ") * (" Y2 " + " Z2 ")) + 17 * " X2
	      " * (" Y2 " + " Z2 ") - 20 * (" X2 " + " Y2 " + " Z2 ") + 17)") " }" },   /* f_torus_gumdrop */
	{ 73, "function(x, y, z, P0) { " FIELD("-(x*x - y*z*z)") " }" },   /* f_umbrella */
	{ 74, "function(x, y, z, P0, P1) { " FIELD("-(P1 * (y - 1) + (x*x + z*z) * y)") " }" },   /* f_witch_of_agnesi */
	{ 75, "function(x, y, z, P0, P1, P2, P3, P4, P5) { " FIELD("-(P1*P1 * " C2Y " + " SQ(C2X) " * " C2Y " - P2)") " }" },
	                                                                                      /* f_witch_of_agnesi_2d */
};

/* The internal functions that are one op of their own on all their
 * parameters (scene.h's FOP_), those POV-Ray's function language cannot write:
 * they loop a number of times a parameter says, or read the noise. f_noise3d,
 * internal(76), is POV-Ray's Noise at (x, y, z) with the scene's
 * noise_generator. */
static const struct {
	int number, op, n_params;
} op_internals[] = {
	{ 76, FOP_NOISE3, 3 },   /* f_noise3d */
	{ 78, FOP_NOISE4, 4 },   /* f_noise_generator */
	{ 29, FOP_HETERO_MF, 9 },   /* f_hetero_mf */
	{ 58, FOP_RIDGE, 9 },   /* f_ridge */
	{ 59, FOP_RIDGED_MF, 9 },   /* f_ridged_mf */
	{ 52, FOP_POLYTUBES, 9 },   /* f_polytubes */
};

int eval_internal_op(int number, int *n_params)
{
	for (size_t k = 0; k < sizeof op_internals / sizeof *op_internals; k++)
		if (op_internals[k].number == number) {
			*n_params = op_internals[k].n_params;
			return op_internals[k].op;
		}
	return -1;
}

const ast_node *eval_internal_function(int number)
{
	static ast_node *parsed[sizeof internals / sizeof *internals];
	for (size_t i = 0; i < sizeof internals / sizeof *internals; i++) {
		if (internals[i].number != number)
			continue;
		if (!parsed[i]) {   /* kept for the process: a few small trees */
			char name[32], *text = NULL;
			snprintf(name, sizeof name, "internal(%d)", number);
			if (asprintf(&text, "#declare F = %s\n", internals[i].text) < 0)
				return NULL;
			ast_node *file = parse_text(name, text, strlen(text));
			if (!file || file->n_kids != 1 || file->kids[0]->kind != AST_DECLARE ||
			    file->kids[0]->kids[0]->kind != AST_FUNCTION)
				return NULL;
			parsed[i] = file;
		}
		return parsed[i]->kids[0]->kids[0];
	}
	return NULL;
}
