/* test_function.c: POV-Ray functions through the whole pipeline (the scene
 * text parsed and evaluated into programs, written as OpenCL C by lowering,
 * built into the kernels and run by kernels/raycast.cl's function_values)
 * against the same expressions written here in C, in double precision, and
 * against the host's run of the programs (scene_function_eval).
 *
 * Each case is one function { } of a pigment, evaluated at random points; one
 * ok/FAIL line a case. Then the text lowering writes is checked for what the
 * scene wrote: strings that look like code, folded into constants, must leave
 * no quote, '#' or comment in it.
 *
 * Isosurfaces: rays cast through the kernels (kernels/raycast.cl) at each of a
 * few isosurfaces hit where the host's trace() (src/shape_isosurface.c, the
 * same search in double) says, within the search's own step, accuracy, and
 * trace() agrees with the sphere's closed form; the host's inside test agrees
 * with trace()'s crossings (tests/cast.c).
 *
 *   test_function [POINTS] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cast.h"
#include "device.h"
#include "diag.h"
#include "eval.h"
#include "lower.h"
#include "parse.h"

static double sel3(double a, double b, double c)
{
	return a < 0 ? b : c;
}

static double f0(double a, double b)   /* F0 below, with K = 3 */
{
	return sin(a * 3) * cos(b * 3);
}

/* Each case: the body of function { } in POV-Ray's language, and the same in C
 * (NULL: the device against the host's run alone). */
static double c_arith(double x, double y, double z) { return x * y - z / 2 + 1; }
static double c_declared(double x, double y, double z) { (void)z; return f0(x, y); }
static double c_calls(double x, double y, double z) { return f0(x, z) + f0(z, y) * f0(y, x); }
static double c_select(double x, double y, double z)
{
	return sel3(x, y, z) + (y - 1 < 0 ? 1 : y - 1 == 0 ? 2 : 3);
}
static double c_minmax(double x, double y, double z) { return fmin(fmin(x, y), z) + fmax(x, 2 * y); }
static double c_powmod(double x, double y, double z)
{
	return pow(fabs(x), 1.5) + fmod(y * 4, 1) + trunc(z * 4 / 1.5);
}
static double c_logic(double x, double y, double z)
{
	return (x < y) + (y <= z) * 2 + (x > z) * 4 + (y >= x) * 8 + (x != y) * 16 + (x == x) * 32 +
	       ((x > 0) && (y > 0)) * 64 + ((x > 0) || !(y > 0)) * 128;
}
static double c_exp(double x, double y, double z)
{
	return exp(-x * x) + log(fabs(y) + 1) + log10(fabs(z) + 1) + sqrt(fabs(x)) + atan2(y, x) + floor(z) +
	       ceil(x) + trunc(y);
}
static double c_trig(double x, double y, double z)
{
	return tan(x / 4) + asin(x / 3.5) + acos(y / 3.5) + atan(z) + sinh(x / 2) + cosh(y / 2) + tanh(z) + asinh(x) +
	       acosh(fabs(y) + 1) + atanh(z / 3.5) + x * 180 / M_PI + y * M_PI / 180;
}
static double c_folded(double x, double y, double z) { (void)z; return x * M_PI + 2 * y + 16; }   /* the string has 16 characters */
static double c_nested(double x, double y, double z)
{
	double s = 0;
	for (int i = 0; i < 40; i++)
		s = (s + x) * 0.5 + y * z / 8;
	return -(-(-s));
}

/* POV-Ray's internal functions as POV-Ray 3.7 writes them (source/vm/fnintern.cpp),
 * with the parameters the cases below give them; eclat writes them in POV-Ray's
 * own language (src/eval_internal.c). */
static double c_rounded_box(double x, double y, double z)
{
	double p0 = 0.2, p1 = 0.8, p2 = 0.5, p3 = 0.6;
	double x2 = p1 - p0, y2 = p2 - p0, z2 = p3 - p0;
	double x3 = x < x2 ? 0 : x - x2, y3 = y < y2 ? 0 : y - y2, z3 = z < z2 ? 0 : z - z2;
	x2 = p0 - p1, y2 = p0 - p2, z2 = p0 - p3;
	x = x > x2 ? 0 : x2 - x, y = y > y2 ? 0 : y2 - y, z = z > z2 ? 0 : z2 - z;
	x = fmax(x, x3), y = fmax(y, y3), z = fmax(z, z3);
	return -p0 + sqrt(x * x + y * y + z * z) - 1e-6;
}
static double c_torus_th_ph(double x, double y, double z)
{
	double r = sqrt(x * x + z * z) - 0.7;
	return -0.25 + sqrt(r * r + y * y) + atan2(x, z) + atan2(sqrt(x * x + z * z), y) +
	       (-0.5 + sqrt(x * x + y * y + z * z)) + sqrt(x * x + y * y + z * z) + sqrt(x * x * 4 + y * y + z * z * 9);
}
static double c_fields(double x, double y, double z)
{
	double x2 = x * x, y2 = y * y, z2 = z * z, ph = 0.5 * 0.5, th = 0.2 * 0.2;
	double torus2 = -(x2 * x2 + y2 * y2 + z2 * z2 + 2 * x2 * y2 + 2 * x2 * z2 + 2 * y2 * z2 - 2 * (ph + th) * x2 +
	                  2 * (ph - th) * y2 - 2 * (ph + th) * z2 + (ph - th) * (ph - th));
	double heart = -((2 * x2 + y2 + z2 - 1) * (2 * x2 + y2 + z2 - 1) * (2 * x2 + y2 + z2 - 1) - 0.1 * x2 * z2 * z -
	                 y2 * z2 * z);
	double cross = fmax(exp(-(x2 * 2 + y2 * 2 + z2) * 3), exp(-(x2 * 2 + y2 + z2 * 2) * 3));
	cross = 1 - fmax(cross, exp(-(x2 + y2 * 2 + z2 * 2) * 3)) * 0.5;
	double super = 1 - pow(pow(pow(fabs(x), 2 / 0.5) + pow(fabs(y), 2 / 0.5), 0.5 / 0.7) + pow(fabs(z), 2 / 0.7),
	                       0.7 * 0.5);
	return fmin(10, fmax(1.5 * torus2, -10)) + fmin(10, fmax(0.3 * heart, -10)) + cross + super;
}
static double c_more_fields(double x, double y, double z)
{
	double x2 = x * x, y2 = y * y, z2 = z * z;
	double flange = 1.2 - (exp(-(x2 * 2 + y2 * 2 + z2) * 3) + exp(-(x2 * 2 + y2 + z2 * 2) * 3) +
	                       exp(-(x2 + y2 * 2 + z2 * 2) * 3)) * 0.5;
	double mitre = -(4 * x2 * (x2 + y2 + z2) - y2 * (1 - y2 - z2));
	double para = -(x2 - y + z2);
	double qcyl = -((x2 + z2) * y2 + 0.4 * 0.4 * (x2 + z2) - 0.4 * 0.4 * 0.3 * 0.3);
	double witch = -(0.6 * (y - 1) + (x2 + z2) * y);
	return flange + fmin(10, fmax(2 * mitre, -10)) + fmin(10, fmax(1.5 * para, -10)) +
	       fmin(10, fmax(3 * qcyl, -10)) + fmin(10, fmax(0.8 * witch, -10));
}

/* f_noise3d: the host's port of the device's noise (scene_noise), which
 * test_pattern holds to POV-Ray's own images; here the device's and the
 * host's runs of a function using it must agree. */
static double c_noise(double x, double y, double z)
{
	float a[3] = { (float)(2 * x), (float)y, (float)(z - 1) }, b[3] = { (float)x, (float)y, (float)z };
	return 0.5 * scene_noise(a, 2) + scene_noise(b, 2);
}

static const struct {
	const char *name, *body;
	double (*c)(double, double, double);
} cases[] = {
	{ "f_noise3d", "f_noise3d(2 * x, y, z - 1) * 0.5 + f_noise3d(x, y, z)", c_noise },
	/* the other internal functions against the host's run only: tests/eval's
	 * internal_*.scn hold the host's to POV-Ray's own values */
	{ "functions.inc's algebraic surfaces",
	  "f_bicorn(x, y, z, 1, 0.8) + f_bifolia(x, y, z, 1, 3) + f_boy_surface(x, y, z, 0.01, 0.05)"
	  " + f_crossed_trough(x, y, z, 1) + f_cubic_saddle(x, y, z, 1) + f_cushion(x, y, z, 1)"
	  " + f_devils_curve(x, y, z, 1) + f_dupin_cyclid(x, y, z, 0.001, 4.9, 5, 2, 0, 3)"
	  " + f_enneper(x, y, z, 1) + f_folium_surface(x, y, z, 1, 1, 1) + f_glob(x, y, z, 1)"
	  " + f_hunt_surface(x, y, z, 0.001) + f_hyperbolic_torus(x, y, z, 1, 0.5, 0.25)"
	  " + f_kampyle_of_eudoxus(x, y, z, 1, 0.2, 1.5) + f_klein_bottle(x, y, z, 1)"
	  " + f_kummer_surface_v1(x, y, z, 1) + f_kummer_surface_v2(x, y, z, 1, -0.97, -0.5, 0.3)"
	  " + f_lemniscate_of_gerono(x, y, z, 1) + f_nodal_cubic(x, y, z, 1) + f_odd(x, y, z, 1)"
	  " + f_ovals_of_cassini(x, y, z, 1, 0.5, 0.3, 1.2) + f_parabolic_torus(x, y, z, 1, 0.6, 0.3)"
	  " + f_pillow(x, y, z, 1) + f_piriform(x, y, z, 1) + f_quartic_paraboloid(x, y, z, 1)"
	  " + f_quartic_saddle(x, y, z, 1) + f_steiners_roman(x, y, z, 1)"
	  " + f_strophoid(x, y, z, 1, 0.4, 0.6, 1.5) + f_torus_gumdrop(x, y, z, 0.1) + f_umbrella(x, y, z, 1)", NULL },
	{ "the SOR switch off, on, and turned",
	  "f_algbr_cyl1(x, y, z, 1, 5, 0, 0, 0) + f_algbr_cyl1(x, y, z, 1, 5, 1, 0.3, 0)"
	  " + f_algbr_cyl2(x, y, z, 1, 5, 1, 0.2, 25) + f_algbr_cyl3(x, y, z, 1, 5, 1, 0.3, 0)"
	  " + f_algbr_cyl4(x, y, z, 1, 5, 0, 0, 0) + f_devils_curve_2d(x, y, z, 1, 0.6, 0.5, 1, 0.2, 25)"
	  " + f_folium_surface_2d(x, y, z, 1, 1, 1, 1, 0.3, 0) + f_kampyle_of_eudoxus_2d(x, y, z, 1, 0.2, 1.5, 0, 0, 0)"
	  " + f_lemniscate_of_gerono_2d(x, y, z, 1, 1.2, 0.8, 1, 0.2, 25)"
	  " + f_piriform_2d(x, y, z, 1, 1, -1, 0.8, 1, 0.3, 0) + f_strophoid_2d(x, y, z, 1, 0.4, 0.6, 1.5, 1, 0.2, 25)"
	  " + f_witch_of_agnesi_2d(x, y, z, 1, 0.5, 0.3, 1, 0.3, 0)", NULL },
	{ "functions.inc's other shapes",
	  "f_blob(x, y, z, 1, 1, 0.8, 1, 1.2) + f_blob2(x, y, z, 0.6, 2, 1, 0.2) + f_comma(x, y, z, 1)"
	  " + f_helical_torus(x, y, z, 0.6, 5, 2, 0.1, 0.05, 0.2, 0.5, 3, 0.8, 1)"
	  " + f_helix2(x, y, z, 0, 6, 0.1, 0.3, 0, 1, 0) + f_helix2(x, y, z, 0, 6, 0.1, 0.3, 0, 0.5, 0)"
	  " + f_helix2(x, y, z, 0, 6, 0.1, 0.3, 0, 0, 0) + f_hex_x(x, y, z, 0) + f_hex_y(x, y, z, 0)"
	  " + f_isect_ellipsoids(x, y, z, 3, 1.5, 1, 0.1) + f_mesh1(x, y, z, 0.3, 0.4, 2, 0.1, 1.5)"
	  " + f_poly4(x, y, z, 0.2, 0.1, -0.3, 0.05, 0.4) + f_polytubes(x, y, z, 5, 0.3, 0.1, -0.2, 0.05, 0.1)"
	  " + f_polytubes(x, y, z, 2.7, 0.3, 0.1, -0.2, 0.05, 0.1) + f_quantum(x, y, z, 0)"
	  " + f_spikes(x, y, z, 0.1, 20, 2, 1.5, 0.9) + f_spikes_2d(x, y, z, 0.8, 9, 7, 3)"
	  " + f_spiral(x, y, z, 0.3, 0.1, 1, 0, 0, 1) + f_spiral(x, y, z, 0.3, 0.1, 1, 0, 0, 0.5)"
	  " + f_spiral(x, y, z, 0.3, 0.1, 1, 0, 0, 0)", NULL },
	{ "f_noise_generator, f_hetero_mf, f_ridge, f_ridged_mf",
	  "f_noise_generator(x, y, z, 1) + f_noise_generator(x, y, z, 3) + f_hetero_mf(x, y, z, 0.5, 2, 3.5, 0.8, 1, 2)"
	  " + f_ridge(x, y, z, 2, 2.5, 0.5, 0.3, 0.5, 3) + f_ridged_mf(x, y, z, 0.5, 2, 4, 1, 2, 2)", NULL },
	/* hostile counts end (clamped to 64 octaves, 256 tubes), the same on both */
	{ "octaves, exponents, tubes and generators of 1e9 and below 0",
	  "f_ridged_mf(x, y, z, 0.5, 2, 1e9, 1, 2, 1e30) + f_hetero_mf(x, y, z, 0.5, 2, -3.5, 0.8, 1e9, -7)"
	  " + f_hetero_mf(x, y, z, 0.5, 1.1, 1e9, 0.1, 2, 1) + f_ridge(x, y, z, 2, 1e9, 0.5, 0.3, 0.5, -1e12)"
	  " + f_ridge(x, y, z, 2, -2.5, 0.5, 0.3, 0.5, 2) + f_polytubes(x, y, z, 1e9, 0.3, 0, 0, 0, 0)"
	  " + f_polytubes(x, y, z, -3, 0.3, 0, 0, 0, 0)", NULL },
	{ "a count or generator that is NaN (f_ridged_mf and f_polytubes finite)",
	  "f_ridged_mf(x, y, z, 0.5, 2, sqrt(-1 - x*x), 1, 2, sqrt(-1 - y*y)) + f_polytubes(x, y, z, sqrt(-1 - z*z), 0.3,"
	  " 0, 0, 0, 0) + f_noise_generator(x, y, z, sqrt(-1 - x*x))", NULL },
	{ "f_hetero_mf and f_ridge of NaN octaves (NaN)",
	  "f_hetero_mf(x, y, z, 0.5, 2, sqrt(-1 - x*x), 0.8, 1, 2) + f_ridge(x, y, z, 2, sqrt(-1 - y*y), 0.5, 0.3, 0.5, 2)",
	  NULL },
	{ "f_flange_cover, f_mitre, f_paraboloid, f_quartic_cylinder, f_witch_of_agnesi",
	  "f_flange_cover(x, y, z, 2, 3, 0.5, 1.2) + f_mitre(x, y, z, 2) + f_paraboloid(x, y, z, 1.5)"
	  " + f_quartic_cylinder(x, y, z, 3, 0.3, 0.4) + f_witch_of_agnesi(x, y, z, 0.8, 0.6)", c_more_fields },
	{ "f_rounded_box", "f_rounded_box(x, y, z, 0.2, 0.8, 0.5, 0.6)", c_rounded_box },
	{ "f_torus, f_th, f_ph, f_sphere, f_r, f_ellipsoid",
	  "f_torus(x, y, z, 0.7, 0.25) + f_th(x, y, z) + f_ph(x, y, z) + f_sphere(x, y, z, 0.5) + f_r(x, y, z)"
	  " + f_ellipsoid(x, y, z, 2, 1, 3)", c_torus_th_ph },
	{ "f_torus2, f_heart, f_cross_ellipsoids, f_superellipsoid",
	  "f_torus2(x, y, z, 1.5, 0.5, 0.2) + f_heart(x, y, z, 0.3) + f_cross_ellipsoids(x, y, z, 2, 3, 0.5, 1)"
	  " + f_superellipsoid(x, y, z, 0.5, 0.7)", c_fields },
	{ "arithmetic", "x * y - z / 2 + 1", c_arith },
	{ "a declared function with named parameters", "F0(x, y)", c_declared },
	{ "calls of calls", "F1(x, y, z)", c_calls },
	{ "select of three and of four", "select(x, y, z) + select(y - 1, 1, 2, 3)", c_select },
	{ "min and max of several", "min(x, y, z) + max(x, 2 * y)", c_minmax },
	{ "pow, mod and div", "pow(abs(x), 1.5) + mod(y * 4, 1) + div(z * 4, 1.5)", c_powmod },
	{ "comparisons and logic", "(x < y) + (y <= z) * 2 + (x > z) * 4 + (y >= x) * 8 + (x != y) * 16 + (x = x) * 32"
	  " + (x > 0 & y > 0) * 64 + (x > 0 | !(y > 0)) * 128", c_logic },
	{ "exp, ln, log, sqrt, atan2, floor, ceil, int",
	  "exp(-x * x) + ln(abs(y) + 1) + log(abs(z) + 1) + sqrt(abs(x)) + atan2(y, x) + floor(z) + ceil(x) + int(y)",
	  c_exp },
	{ "trigonometry", "tan(x / 4) + asin(x / 3.5) + acos(y / 3.5) + atan(z) + sinh(x / 2) + cosh(y / 2) + tanh(z)"
	  " + asinh(x) + acosh(abs(y) + 1) + atanh(z / 3.5) + degrees(x) + radians(y)", c_trig },
	{ "constants folded by the host", "x * pi + V.y * y + strlen(\"*/ #define x \\\" \\\\\")", c_folded },
	{ "forty levels deep", NULL, c_nested },
};
#define N_CASES (int)(sizeof cases / sizeof *cases)

static int failures;

/* The isosurfaces, each moved 20 units along x from the one before. */
static const struct {
	const char *name, *text;
	double radius;   /* > 0: the sphere of this radius about the origin, in closed form */
} isos[] = {
	{ "a sphere", "function { x * x + y * y + z * z - 0.64 } accuracy 0.0001 max_gradient 4", 0.8 },
	{ "a wavy ball in a sphere, turned and scaled",
	  "function { x * x + y * y + z * z - 0.6 + 0.1 * sin(6 * x) * sin(6 * y) } contained_by { sphere { 0, 1 } }"
	  " max_gradient 3 scale <1, 0.7, 1.2> rotate <20, 30, 40>", 0 },
	{ "an open wave", "function { y + 0.3 * sin(3 * x) * cos(2 * z) } open max_gradient 1.5", 0 },
	{ "a cylinder capped by its box, every crossing",
	  "function { x * x + z * z } threshold 0.25 contained_by { box { <-1, -0.5, -1>, <1, 0.5, 1> } } "
	  "all_intersections max_gradient 3 accuracy 0.0001", 0 },
	{ "a shell of positive polarity", "function { x * x + y * y + z * z } threshold 0.3 polarity 1 "
	  "max_trace 4 max_gradient 2 accuracy 0.0001 contained_by { sphere { 0, 0.9 } }", 0 },
};
#define N_ISO (int)(sizeof isos / sizeof *isos)

static char *scene_text(size_t *len)
{
	char *text = NULL;
	FILE *f = open_memstream(&text, len);
	fputs("#version 3.7;\n#declare K = 3;\n#declare V = <1, 2, 3>;\n"
	      "#declare F0 = function(a, b) { sin(a * K) * cos(b * K) }\n"
	      "#declare F1 = function { F0(x, z) + F0(z, y) * F0(y, x) }\n", f);
	static const char *const internal[] = {   /* all of functions.inc's */
		"f_algbr_cyl1 0", "f_algbr_cyl2 1", "f_algbr_cyl3 2", "f_algbr_cyl4 3", "f_bicorn 4", "f_bifolia 5",
		"f_blob 6", "f_blob2 7", "f_boy_surface 8", "f_comma 9", "f_cross_ellipsoids 10", "f_crossed_trough 11",
		"f_cubic_saddle 12", "f_cushion 13", "f_devils_curve 14", "f_devils_curve_2d 15", "f_dupin_cyclid 16",
		"f_ellipsoid 17", "f_enneper 18", "f_flange_cover 19", "f_folium_surface 20", "f_folium_surface_2d 21",
		"f_glob 22", "f_heart 23", "f_helical_torus 24", "f_helix1 25", "f_helix2 26", "f_hex_x 27", "f_hex_y 28",
		"f_hetero_mf 29", "f_hunt_surface 30", "f_hyperbolic_torus 31", "f_isect_ellipsoids 32",
		"f_kampyle_of_eudoxus 33", "f_kampyle_of_eudoxus_2d 34", "f_klein_bottle 35", "f_kummer_surface_v1 36",
		"f_kummer_surface_v2 37", "f_lemniscate_of_gerono 38", "f_lemniscate_of_gerono_2d 39", "f_mesh1 40",
		"f_mitre 41", "f_nodal_cubic 42", "f_odd 43", "f_ovals_of_cassini 44", "f_paraboloid 45",
		"f_parabolic_torus 46", "f_ph 47", "f_pillow 48", "f_piriform 49", "f_piriform_2d 50", "f_poly4 51",
		"f_polytubes 52", "f_quantum 53", "f_quartic_paraboloid 54", "f_quartic_saddle 55",
		"f_quartic_cylinder 56", "f_r 57", "f_ridge 58", "f_ridged_mf 59", "f_rounded_box 60", "f_sphere 61",
		"f_spikes 62", "f_spikes_2d 63", "f_spiral 64", "f_steiners_roman 65", "f_strophoid 66",
		"f_strophoid_2d 67", "f_superellipsoid 68", "f_th 69", "f_torus 70", "f_torus2 71", "f_torus_gumdrop 72",
		"f_umbrella 73", "f_witch_of_agnesi 74", "f_witch_of_agnesi_2d 75", "f_noise3d 76", "f_noise_generator 78"
	};
	for (size_t i = 0; i < sizeof internal / sizeof *internal; i++) {   /* as functions.inc declares them */
		char name[32];
		int n;
		sscanf(internal[i], "%31s %d", name, &n);
		fprintf(f, "#declare %s = function { internal(%d) }\n", name, n);
	}
	for (int i = 0; i < N_CASES; i++) {
		fputs("sphere { 1000, 0.001 pigment { function { ", f);
		if (cases[i].body) {
			fputs(cases[i].body, f);
		} else {   /* c_nested: s = (s + x) * 0.5 + y * z / 8, forty times */
			fputs("-(-(-(", f);
			for (int k = 0; k < 40; k++)
				fputs("((", f);
			fputs("0", f);
			for (int k = 0; k < 40; k++)
				fputs(" + x) * 0.5 + y * z / 8)", f);
			fputs(")))", f);
		}
		fputs(" } } }\n", f);
	}
	for (int i = 0; i < N_ISO; i++)
		fprintf(f, "isosurface { %s translate <%d, 0, 0> }\n", isos[i].text, 20 * i);
	fclose(f);
	return text;
}

/* Runs function f at n points (float4 each) into out. */
static int run(device_ctx *dev, cl_program prog, int f, const float *pts, int n, float *out)
{
	cl_int err;
	cl_kernel k = clCreateKernel(prog, "function_values", &err);
	if (!k)
		return -1;
	cl_mem bp = clCreateBuffer(dev->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, (size_t)n * 16, (void *)pts,
	                           &err);
	cl_mem bo = clCreateBuffer(dev->context, CL_MEM_WRITE_ONLY, (size_t)n * sizeof *out, NULL, &err);
	clSetKernelArg(k, 0, sizeof f, &f);
	clSetKernelArg(k, 1, sizeof bp, &bp);
	clSetKernelArg(k, 2, sizeof bo, &bo);
	size_t global = (size_t)n;
	err = clEnqueueNDRangeKernel(dev->queue, k, 1, NULL, &global, NULL, 0, NULL, NULL);
	if (err == CL_SUCCESS)
		err = clEnqueueReadBuffer(dev->queue, bo, CL_TRUE, 0, (size_t)n * sizeof *out, out, 0, NULL, NULL);
	clReleaseMemObject(bp);
	clReleaseMemObject(bo);
	clReleaseKernel(k);
	if (err != CL_SUCCESS)
		fprintf(stderr, "function_values: OpenCL error %d\n", err);
	return err == CL_SUCCESS ? 0 : -1;
}

static bool close_to(double a, double b)
{
	if (isnan(a) || isnan(b))
		return isnan(a) && isnan(b);
	return fabs(a - b) <= 1e-5 * fmax(1, fabs(b));
}

/* The OpenCL lowering wrote: nothing of the scene's text may be in it. */
static void check_source(const char *src)
{
	const char *body = strstr(src, "*/");   /* after the heading comment */
	bool clean = body && !strchr(body + 2, '"') && !strchr(body + 2, '#') && !strstr(body + 2, "/*") &&
	             !strstr(body + 2, "define");
	printf("%s: the functions' OpenCL holds no text of the scene\n", clean ? "ok" : "FAIL");
	failures += !clean;
}

/* Programs made here, not by the evaluator (issue 20): constants that are no
 * finite number must still be written as OpenCL C that builds (a stand-in for
 * the kernels' real and noise is enough to build it), and a program that breaks
 * scene.h's promises (a stack too short, a call of a later function, an op that
 * is none) must be refused, never written. */
static void check_hand_made(device_ctx *dev)
{
	scene s;
	scene_init(&s);
	scene_fop odd[] = { { FOP_PARAM, 0, 0 }, { FOP_CONST, 0, NAN }, { FOP_ADD, 0, 0 }, { FOP_CONST, 0, INFINITY },
	                    { FOP_MUL, 0, 0 }, { FOP_CONST, 0, -INFINITY }, { FOP_SUB, 0, 0 }, { FOP_CONST, 0, 1e308 },
	                    { FOP_CONST, 0, -0.0 }, { FOP_CONST, 0, 4.9e-324 }, { FOP_SELECT3, 0, 0 }, { FOP_ADD, 0, 0 } };
	scene_function fn = { .n_params = 1, .ops = malloc(sizeof odd), .n_ops = (int)(sizeof odd / sizeof *odd) };
	memcpy(fn.ops, odd, sizeof odd);
	scene_add_function(&s, &fn);
	char *src = lower_function_source(&s, NULL);
	const char *prelude = "typedef float real;\ntypedef struct scene_data scene_data;\n"
	                      "float pattern_noise(float3 p, int g) { return p.x + g; }\n";
	const char *parts[2] = { prelude, src ? src : "" };
	cl_int err;
	cl_program p = clCreateProgramWithSource(dev->context, 2, parts, NULL, &err);
	bool built = src && p && clBuildProgram(p, 1, &dev->device, "", NULL, NULL) == CL_SUCCESS;
	printf("%s: NaN, infinities, -0 and a denormal as constants build as OpenCL C\n", built ? "ok" : "FAIL");
	if (!built && src)
		printf("%s", src);
	failures += !built;
	if (p)
		clReleaseProgram(p);
	free(src);
	static const scene_fop broken[][2] = {
		{ { FOP_CONST, 0, 1 }, { FOP_ADD, 0, 0 } },      /* a stack too short */
		{ { FOP_CONST, 0, 1 }, { FOP_CALL, 5, 0 } },     /* a call of a later function */
		{ { FOP_PARAM, 3, 0 }, { FOP_NEG, 0, 0 } },      /* a parameter it does not have */
		{ { FOP_CONST, 0, 1 }, { FOP_COUNT + 7, 0, 0 } },   /* no op */
	};
	for (size_t i = 0; i < sizeof broken / sizeof *broken; i++) {
		scene b;
		scene_init(&b);
		scene_function bf = { .n_params = 1, .ops = malloc(sizeof broken[i]), .n_ops = 2 };
		memcpy(bf.ops, broken[i], sizeof broken[i]);
		scene_add_function(&b, &bf);
		char *bsrc = lower_function_source(&b, NULL);
		printf("%s: a malformed program (%zu) is refused\n", bsrc ? "FAIL" : "ok", i);
		failures += bsrc != NULL;
		free(bsrc);
		scene_free(&b);
	}
	/* a pattern or pigment op names a pigment of the scene, and a channel of 0 to 5 */
	static const scene_fop patterns[][4] = {
		{ { FOP_PARAM, 0, 0 }, { FOP_PARAM, 0, 0 }, { FOP_PARAM, 0, 0 }, { FOP_PATTERN, 0, 0 } },
		{ { FOP_PARAM, 0, 0 }, { FOP_PARAM, 0, 0 }, { FOP_PARAM, 0, 0 }, { FOP_PIGMENT, -1, 0 } },
	};
	for (size_t i = 0; i < sizeof patterns / sizeof *patterns; i++) {
		scene b;
		scene_init(&b);
		scene_function bf = { .n_params = 1, .ops = malloc(sizeof patterns[i]), .n_ops = 4 };
		memcpy(bf.ops, patterns[i], sizeof patterns[i]);
		scene_add_function(&b, &bf);
		char *bsrc = lower_function_source(&b, NULL);
		printf("%s: a pattern op of a pigment the scene lacks (%zu) is refused\n", bsrc ? "FAIL" : "ok", i);
		failures += bsrc != NULL;
		free(bsrc);
		scene_free(&b);
	}
	scene_free(&s);
}

/* The sphere of radius r about c: the ray's nearest hit after 0, or INFINITY. */
static double sphere_hit(const double c[3], double r, const double o[3], const double d[3])
{
	double oc[3] = { o[0] - c[0], o[1] - c[1], o[2] - c[2] };
	double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2], b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
	double disc = b * b - a * (oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - r * r);
	if (disc < 0)
		return INFINITY;
	double t0 = (-b - sqrt(disc)) / a, t1 = (-b + sqrt(disc)) / a;
	return t0 > 0 ? t0 : t1 > 0 ? t1 : INFINITY;
}

static void test_isosurface(device_ctx *dev, cl_program prog, const scene *s, const lower_result *lr, int i,
                            int n_rays)
{
	const scene_object *o = &s->objects[N_CASES + i];
	cast_shape sh = { .s = s, .o = o };
	lower_invert(&o->xf, &sh.inv);
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY }, mid[3];
	shape_of(o)->bounds(s, o, lo, hi);
	double size = 0;
	for (int k = 0; k < 3; k++) {
		mid[k] = (lo[k] + hi[k]) / 2;
		size = fmax(size, hi[k] - lo[k]);
	}
	float *rays = malloc((size_t)n_rays * 8 * sizeof *rays), *hits = malloc((size_t)n_rays * 4 * sizeof *hits);
	for (int r = 0; r < n_rays; r++) {   /* from around it toward a point of its box, unit length */
		double d[3], to[3], l = 0;
		cast_random_unit(d);
		for (int k = 0; k < 3; k++) {
			to[k] = lo[k] + cast_uniform() * (hi[k] - lo[k]);
			d[k] = to[k] - (mid[k] + 2 * size * d[k]);
			l += d[k] * d[k];
		}
		for (int k = 0; k < 3; k++) {
			rays[8 * r + k] = (float)(to[k] - d[k]);
			rays[8 * r + 4 + k] = (float)(d[k] / sqrt(l));
		}
		rays[8 * r + 3] = 1e30f;
		rays[8 * r + 7] = 0;
	}
	if (cast_rays(dev, prog, "raycast", lr, rays, n_rays, hits, 1, -1)) {
		failures++;
		free(rays);
		free(hits);
		return;
	}
	/* Both search the same grid of steps shorter than accuracy from where the
	 * ray enters the container; the float ray moves the grid a little, so a
	 * hit may land one step off, and a ray that grazes a sliver of the surface
	 * thinner than a step may see it on one side only. */
	int wrong = 0, grazing = 0, hit_count = 0, closed_form_bad = 0;
	double step = 2 * o->param[1] * fmax(1, size);
	for (int r = 0; r < n_rays; r++) {
		const float *ray = rays + 8 * r;
		double wo[3] = { ray[0], ray[1], ray[2] }, wd[3] = { ray[4], ray[5], ray[6] };
		int prim;
		memcpy(&prim, &hits[4 * r + 1], sizeof prim);
		bool mine = prim >= 0 && lr->prims[prim].object == N_CASES + i;
		double td = mine ? hits[4 * r] : INFINITY, th = cast_trace(&sh, wo, wd, NULL);
		hit_count += isfinite(th);
		if (isos[i].radius > 0) {   /* the sphere: trace() against the closed form */
			double c[3] = { o->xf.m[0][3], o->xf.m[1][3], o->xf.m[2][3] };
			double ta = sphere_hit(c, isos[i].radius, wo, wd), oc[3], along = 0, miss = 0;
			for (int k = 0; k < 3; k++) {
				oc[k] = c[k] - wo[k];
				along += oc[k] * wd[k];
			}
			for (int k = 0; k < 3; k++)
				miss += (oc[k] - along * wd[k]) * (oc[k] - along * wd[k]);
			bool grazes = fabs(sqrt(miss) - isos[i].radius) < 1e-3;   /* the silhouette's sliver */
			closed_form_bad += isfinite(ta) != isfinite(th) ? !grazes : isfinite(ta) && fabs(ta - th) > step;
		}
		if ((isinf(td) && isinf(th)) || fabs(td - th) <= step)
			continue;
		if (isinf(td) != isinf(th) || fabs(td - th) > step) {
			double jo[3], tj;   /* grazing: a ray moved by a step sees the device's answer */
			bool agrees = false;
			for (int j = 0; j < 6 && !agrees; j++) {
				for (int k = 0; k < 3; k++)
					jo[k] = wo[k] + (k == j / 2 ? (j % 2 ? step : -step) : 0);
				tj = cast_trace(&sh, jo, wd, NULL);
				agrees = (isinf(td) && isinf(tj)) || fabs(td - tj) <= 2 * step;
			}
			if (agrees) {
				grazing++;
				continue;
			}
		}
		if (wrong++ < 3)
			printf("  ray <%.9g, %.9g, %.9g> <%.9g, %.9g, %.9g>: device t %.9g, host %.9g\n", wo[0], wo[1], wo[2],
			       wd[0], wd[1], wd[2], td, th);
	}
	bool ok = wrong == 0 && grazing <= n_rays / 100 && closed_form_bad == 0 && hit_count > n_rays / 10;
	printf("%s: isosurface, %s: %d rays (%d hit), %d disagree, %d graze it, %d off the closed form\n",
	       ok ? "ok" : "FAIL", isos[i].name, n_rays, hit_count, wrong, grazing, closed_form_bad);
	failures += !ok;
	if (!(o->shape_flags & SHAPE_OPEN) && o->param[3] >= 4)   /* every crossing found: inside agrees */
		failures += cast_check_inside(&sh, isos[i].name, lo, hi, size, 2000) != 0;
	free(rays);
	free(hits);
}

int main(int argc, char **argv)
{
	int n = argc > 1 ? atoi(argv[1]) : 4096;
	cast_seed(0x2545f4914f6cdd1dull);
	size_t len;
	char *text = scene_text(&len);
	scene s;
	scene_init(&s);
	ast_node *ast = parse_text("functions", text, len);   /* the source table owns text now */
	lower_result lr;
	if (!ast || eval_scene(ast, &s, NULL) != 0 || diag_error_count() != 0 || lower_scene(&s, NULL, &lr) != 0 ||
	    !lr.functions) {
		printf("FAIL: the scene did not evaluate and lower\n");
		return 1;
	}
	check_source(lr.functions);
	device_ctx dev;
	if (device_open(&dev, -1))
		return 1;
	cl_program prog = device_build(&dev, getenv("ECLAT_KERNEL_DIR"), lower_kernel_options(&lr), lr.functions);
	if (!prog)
		return 1;
	float *pts = malloc((size_t)n * 4 * sizeof *pts), *out = malloc((size_t)n * sizeof *out);
	double *args = malloc((size_t)n * 3 * sizeof *args), *many = malloc((size_t)n * sizeof *many);
	for (int i = 0; i < n * 4; i++)
		pts[i] = (float)(6 * cast_uniform() - 3);
	for (int c = 0; c < N_CASES; c++) {
		const scene_object *o = &s.objects[c];
		int f = (int)s.pigments[o->material.pattern].params[0][0];
		if (run(&dev, prog, f, pts, n, out)) {
			failures++;
			continue;
		}
		/* the host's run at all the points at once (a height field's) must be
		 * the one at each, bit for bit */
		for (int i = 0; i < n; i++)
			for (int k = 0; k < 3; k++)
				args[3 * i + k] = pts[4 * i + k];
		int bad = scene_function_eval_many(&s, f, n, args, many, NULL, NULL) != 0;
		if (bad)
			printf("  scene_function_eval_many failed\n");
		for (int i = 0; i < n; i++) {
			double a[3] = { pts[4 * i], pts[4 * i + 1], pts[4 * i + 2] };
			double host = scene_function_eval(&s, f, a), want = cases[c].c ? cases[c].c(a[0], a[1], a[2]) : host;
			double dev_v = out[i];   /* a float, before the pattern wraps it */
			bool same = many[i] == host || (isnan(many[i]) && isnan(host));
			bool ok = close_to(host, want) && close_to(dev_v, (float)want) && same;
			if (!ok && bad++ < 3)
				printf("  at <%g, %g, %g>: C %.9g, host %.9g (at once %.9g), device %.9g\n", a[0], a[1], a[2], want,
				       host, many[i], dev_v);
		}
		printf("%s: %s: %d points, %d disagree\n", bad ? "FAIL" : "ok", cases[c].name, n, bad);
		failures += bad > 0;
	}
	for (int i = 0; i < N_ISO; i++)
		test_isosurface(&dev, prog, &s, &lr, i, n);
	check_hand_made(&dev);
	free(pts);
	free(out);
	free(args);
	free(many);
	clReleaseProgram(prog);
	device_close(&dev);
	ast_free(ast);
	lower_free(&lr);
	scene_free(&s);
	printf("%s\n", failures ? "FAIL" : "all function checks passed");
	return failures ? 1 : 0;
}
