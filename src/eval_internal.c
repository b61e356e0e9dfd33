/* eval_internal.c: POV-Ray's internal functions (functions.inc's
 * "function { internal(N) }"), written here in POV-Ray's own function
 * language from their definitions in POV-Ray 3.7 (source/vm/fnintern.cpp),
 * so that the device runs them like any function the scene declares: the
 * text is parsed once when a scene first calls one and becomes a program of
 * scene.functions (eval_function.c).
 *
 * A new one is a line of the table: its number, and its text, whose
 * parameters are x, y, z and then P0, P1... as functions.inc lists them. */
#include <stdio.h>
#include <string.h>

#include "eval_int.h"
#include "parse.h"

/* min(10, max(P0 * r, -10)): the "field strength" clamp many of them share. */
#define FIELD(r) "min(10, max(P0 * (" r "), -10))"

/* f_helix1's pieces (fnintern.cpp names them as it reassigns x and z): the
 * angle about y, wound by the helices, in [0, 2 pi) (the origin's x nudged,
 * as POV-Ray does); the point's z along the helix and x off its centre line;
 * both turned by P6 degrees (no turn when P6 is 0: cos 1, sin 0); the cross
 * section's radius for P5 1 (a circle), 0 (a square) or another exponent. */
#define HELIX_TH1 "mod(atan2(z, select(-(abs(x) + abs(z)), x, 0.000001)) * P0 + y * P1 * P0, 2 * pi)"
#define HELIX_TH "(" HELIX_TH1 " + select(" HELIX_TH1 ", 2 * pi, 0))"
#define HELIX_Z "((" HELIX_TH " - pi) / P4 / (P1 * P0))"
#define HELIX_X "(sqrt(x*x + z*z) - P3)"
#define HELIX_XR "(" HELIX_X " * cos(radians(P6)) - " HELIX_Z " * sin(radians(P6)))"
#define HELIX_ZR "(" HELIX_X " * sin(radians(P6)) + " HELIX_Z " * cos(radians(P6)))"
#define HELIX_R2 "(P5 = 1 ? sqrt(" HELIX_X " * " HELIX_X " + " HELIX_Z " * " HELIX_Z ") : (P5 != 0 ?" \
	" pow(pow(abs(" HELIX_XR "), 2 / P5) + pow(abs(" HELIX_ZR "), 2 / P5), P5 * 0.5) :" \
	" max(abs(" HELIX_XR "), abs(" HELIX_ZR "))))"

static const struct {
	int number;
	const char *text;
} internals[] = {
	{ 10, "function(x, y, z, P0, P1, P2, P3) { P3 - P2 * max(exp(-(x*x*P0 + y*y*P0 + z*z) * P1),"
	      " exp(-(x*x*P0 + y*y + z*z*P0) * P1), exp(-(x*x + y*y*P0 + z*z*P0) * P1)) }" },   /* f_cross_ellipsoids */
	{ 17, "function(x, y, z, P0, P1, P2) { sqrt(x*x*P0*P0 + y*y*P1*P1 + z*z*P2*P2) }" },   /* f_ellipsoid */
	{ 19, "function(x, y, z, P0, P1, P2, P3) { P3 - P2 * (exp(-(x*x*P0 + y*y*P0 + z*z) * P1)"
	      " + exp(-(x*x*P0 + y*y + z*z*P0) * P1) + exp(-(x*x + y*y*P0 + z*z*P0) * P1)) }" },   /* f_flange_cover */
	{ 23, "function(x, y, z, P0) { " FIELD("-(pow(2*x*x + y*y + z*z - 1, 3) - 0.1*x*x*z*z*z - y*y*z*z*z)") " }" },
	                                                                                      /* f_heart */
	{ 25, "function(x, y, z, P0, P1, P2, P3, P4, P5, P6) { -P2 + min(P3 + sqrt(x*x + z*z), " HELIX_R2 ") }" },
	                                                                                      /* f_helix1 */
	{ 41, "function(x, y, z, P0) { " FIELD("-(4*x*x*(x*x + y*y + z*z) - y*y*(1 - y*y - z*z))") " }" },   /* f_mitre */
	{ 45, "function(x, y, z, P0) { " FIELD("-(x*x - y + z*z)") " }" },   /* f_paraboloid */
	{ 47, "function { atan2(sqrt(x*x + z*z), y) }" },   /* f_ph */
	{ 56, "function(x, y, z, P0, P1, P2) { " FIELD("-((x*x + z*z) * y*y + P2*P2 * (x*x + z*z) - P2*P2 * P1*P1)")
	      " }" },   /* f_quartic_cylinder */
	{ 57, "function { sqrt(x*x + y*y + z*z) }" },   /* f_r */
	{ 60, "function(x, y, z, P0, P1, P2, P3) { -P0 + sqrt(pow(max(max(P0 - P1 - x, 0), max(x - (P1 - P0), 0)), 2)"
	      " + pow(max(max(P0 - P2 - y, 0), max(y - (P2 - P0), 0)), 2)"
	      " + pow(max(max(P0 - P3 - z, 0), max(z - (P3 - P0), 0)), 2)) - 1e-6 }" },   /* f_rounded_box */
	{ 61, "function(x, y, z, P0) { -P0 + sqrt(x*x + y*y + z*z) }" },   /* f_sphere */
	{ 68, "function(x, y, z, P0, P1) { 1 - pow(pow(pow(abs(x), 2 / P0) + pow(abs(y), 2 / P0), P0 / P1)"
	      " + pow(abs(z), 2 / P1), P1 * 0.5) }" },   /* f_superellipsoid */
	{ 69, "function { atan2(x, z) }" },   /* f_th */
	{ 70, "function(x, y, z, P0, P1) { -P1 + sqrt(pow(sqrt(x*x + z*z) - P0, 2) + y*y) }" },   /* f_torus */
	{ 71, "function(x, y, z, P0, P1, P2) { " FIELD("-(pow(x*x + y*y + z*z, 2) - 2*(P1*P1 + P2*P2)*x*x"
	      " + 2*(P1*P1 - P2*P2)*y*y - 2*(P1*P1 + P2*P2)*z*z + pow(P1*P1 - P2*P2, 2))") " }" },   /* f_torus2 */
	{ 74, "function(x, y, z, P0, P1) { " FIELD("-(P1 * (y - 1) + (x*x + z*z) * y)") " }" },   /* f_witch_of_agnesi */
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
