/* test_pattern.c: kernels/pattern.cl against POV-Ray 3.7 itself.
 *
 *   test_pattern write DIR     writes DIR/NAME.pov for every case and the list DIR/cases
 *   test_pattern compare DIR   reads POV-Ray's DIR/NAME.ppm (16-bit, linear) and
 *                              compares them with pattern_value, one line a case
 *
 * Each case is a plane z = 0 seen by an orthographic camera (a perspective one
 * for aoi), carrying a pattern as a grey mask: a colour map from black to white,
 * or for a discrete pattern a list of greys from 0 to 1. tests/pattern.test
 * renders the scenes with povray between the two steps. The program computes
 * the same camera rays' hits, takes them into the pattern's space (the inverse
 * of the transformations the scene applies to the pigment) and evaluates
 * pattern_value there, through the embedded kernels/shared.h, pattern_tables.cl
 * and pattern.cl and a kernel of its own. A case passes when at least 99.5% of
 * the pixels are within 3/255 of POV-Ray's. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "povray_plane.h"

#define W PLANE_W
#define H PLANE_H

struct pcase {
	const char *name;
	const char *pov;       /* the pattern and its modifiers, inside pigment { } */
	int list;              /* discrete: the number of list entries; 0: a colour map */
	int kind, wave, gen;   /* gen 0: POV-Ray's default, 2 */
	float freq, phase, exponent;
	float p0[4], p1[4];
	struct plane_warp warps[PLANE_MAX_WARPS];
	int n_warps;
	float scale[3], rotate[3], translate[3];   /* written after the pattern; scale 0: none */
	int perspective;
};

/* The turbulence modifiers' defaults: octaves 6, omega 0.5, lambda 2. */
#define TURB(t, classic) PLANE_TURB(t, classic)
#define TURB_FULL(tx, ty, tz, omega, lambda, octaves, classic) \
	{ WARP_TURBULENCE, classic, { tx, ty, tz, omega }, { lambda, octaves }, { 0 } }

static const struct pcase cases[] = {
	{ "agate", "agate", 0, PATTERN_AGATE, WAVE_RAMP, 0, 1, 0, 1, { 1 }, { 0 },
	  { TURB(0, 1) }, 1, { 0 }, { 0 }, { 0 }, 0 },
	{ "agate_turb", "agate agate_turb 0.6 turbulence 0.3 octaves 4", 0, PATTERN_AGATE, WAVE_RAMP, 0, 1, 0, 1,
	  { 0.6f }, { 0 }, { TURB_FULL(0.3f, 0.3f, 0.3f, 0.5f, 2, 4, 1) }, 1, { 0 }, { 0 }, { 0 }, 0 },
	{ "aoi", "aoi", 0, PATTERN_AOI, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 1 },
	{ "boxed", "boxed", 0, PATTERN_BOXED, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 3, 2, 1 }, { 0, 0, 20 }, { 0 }, 0 },
	{ "bozo", "bozo", 0, PATTERN_BOZO, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
	{ "bozo_gen1", "bozo noise_generator 1", 0, PATTERN_BOZO, WAVE_RAMP, 1, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 0 }, { 0 }, { 0 }, 0 },
	{ "bozo_gen3", "bozo noise_generator 3", 0, PATTERN_BOZO, WAVE_RAMP, 3, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 0 }, { 0 }, { 0 }, 0 },
	{ "bozo_transformed", "bozo", 0, PATTERN_BOZO, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 2, 0.5f, 1 }, { 10, 0, 30 }, { 0.3f, -0.7f, 0.2f }, 0 },
	{ "bozo_turbulence", "bozo turbulence 0.5 octaves 3 omega 0.7 lambda 3", 0, PATTERN_BOZO, WAVE_RAMP, 0, 1, 0, 1,
	  { 0 }, { 0 }, { TURB_FULL(0.5f, 0.5f, 0.5f, 0.7f, 3, 3, 1) }, 1, { 0 }, { 0 }, { 0 }, 0 },
	{ "bozo_warp_turbulence", "bozo warp { turbulence <0.3, 0.6, 0> octaves 4 omega 0.4 lambda 2.2 }", 0,
	  PATTERN_BOZO, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { TURB_FULL(0.3f, 0.6f, 0, 0.4f, 2.2f, 4, 0) }, 1,
	  { 0 }, { 0 }, { 0 }, 0 },
	{ "brick", "brick rgb 0, rgb 1", 2, PATTERN_BRICK, WAVE_RAMP, 0, 0, 0, 1, { 8, 3, 4.5f, 0.5f }, { 0 },
	  { { 0 } }, 0, { 0.25f, 0.25f, 0.25f }, { 0 }, { 0 }, 0 },
	{ "brick_size", "brick rgb 0, rgb 1 brick_size <2, 1, 1.5> mortar 0.2", 2, PATTERN_BRICK, WAVE_RAMP, 0, 0, 0, 1,
	  { 2, 1, 1.5f, 0.2f }, { 0 }, { { 0 } }, 0, { 0 }, { 0, 0, 0 }, { 0.1f, 0.2f, 0.3f }, 0 },
	{ "bumps", "bumps", 0, PATTERN_BUMPS, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
	{ "cells", "cells", 0, PATTERN_CELLS, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 0.5f, 0.5f, 0.5f }, { 0 }, { 0 }, 0 },
	{ "checker", "checker rgb 0, rgb 1", 2, PATTERN_CHECKER, WAVE_RAMP, 0, 0, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { 0, 0, 20 }, { 0 }, 0 },
	{ "crackle", "crackle", 0, PATTERN_CRACKLE, WAVE_RAMP, 0, 1, 0, 1, { -1, 1, 0, 2 }, { 0 }, { { 0 } }, 0,
	  { 0 }, { 0 }, { 0 }, 0 },
	{ "crackle_metric1", "crackle metric 1 form <1, 0, 0>", 0, PATTERN_CRACKLE, WAVE_RAMP, 0, 1, 0, 1,
	  { 1, 0, 0, 1 }, { 0 }, { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
	{ "crackle_metric3", "crackle metric 3 offset 0.2 form <-0.5, 1, 0>", 0, PATTERN_CRACKLE, WAVE_RAMP, 0, 1, 0, 1,
	  { -0.5f, 1, 0, 3 }, { 0.2f }, { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
	{ "crackle_solid", "crackle solid", 0, PATTERN_CRACKLE, WAVE_RAMP, 0, 1, 0, 1, { -1, 1, 0, 2 }, { 0, 1 },
	  { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
	{ "cubic", "cubic rgb 0, rgb 0.2, rgb 0.4, rgb 0.6, rgb 0.8, rgb 1", 6, PATTERN_CUBIC, WAVE_RAMP, 0, 0, 0, 1,
	  /* off the diagonals |x| = |y|, where the two renderers' rounding decides */
	  { 0 }, { 0 }, { { 0 } }, 0, { 0 }, { 0 }, { 0.013f, 0.007f, 0.5f }, 0 },
	{ "cylindrical", "cylindrical", 0, PATTERN_CYLINDRICAL, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 3, 3, 3 }, { 0, 0, 30 }, { 0 }, 0 },
	{ "dents", "dents", 0, PATTERN_DENTS, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
	{ "gradient_x", "gradient x", 0, PATTERN_GRADIENT, WAVE_RAMP, 0, 1, 0, 1, { 1, 0, 0 }, { 0 }, { { 0 } }, 0,
	  { 0 }, { 0 }, { 0 }, 0 },
	{ "gradient_diagonal", "gradient <1, 2, 0> frequency 2 phase 0.3", 0, PATTERN_GRADIENT, WAVE_RAMP, 0, 2, 0.3f, 1,
	  { 1, 2, 0 }, { 0 }, { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
	{ "granite", "granite", 0, PATTERN_GRANITE, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 4, 4, 4 }, { 0 }, { 0 }, 0 },
	{ "granite_gen1", "granite noise_generator 1", 0, PATTERN_GRANITE, WAVE_RAMP, 1, 1, 0, 1, { 0 }, { 0 },
	  { { 0 } }, 0, { 4, 4, 4 }, { 0 }, { 0 }, 0 },
	{ "hexagon", "hexagon rgb 0, rgb 0.5, rgb 1", 3, PATTERN_HEXAGON, WAVE_RAMP, 0, 0, 0, 1, { 0 }, { 0 },
	  { { 0 } }, 0, { 0.5f, 0.5f, 0.5f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "leopard", "leopard", 0, PATTERN_LEOPARD, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 0.3f, 0.3f, 0.3f }, { 0 }, { 0 }, 0 },
	{ "marble", "marble turbulence 0.5", 0, PATTERN_MARBLE, WAVE_TRIANGLE, 0, 1, 0, 1, { 0 }, { 0 },
	  { TURB(0.5f, 1) }, 1, { 0 }, { 0 }, { 0 }, 0 },
	{ "marble_sine", "marble sine_wave frequency 0.5", 0, PATTERN_MARBLE, WAVE_SINE, 0, 0.5f, 0, 1, { 0 }, { 0 },
	  { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
	{ "onion", "onion", 0, PATTERN_ONION, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 2, 2, 2 }, { 0 }, { 0 }, 0 },
	{ "onion_negative_frequency", "onion frequency -1.5 phase 0.2", 0, PATTERN_ONION, WAVE_RAMP, 0, -1.5f, 0.2f, 1,
	  { 0 }, { 0 }, { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
	{ "planar", "planar", 0, PATTERN_PLANAR, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 3, 3, 3 }, { 0 }, { 0 }, 0 },
	{ "quilted", "quilted", 0, PATTERN_QUILTED, WAVE_RAMP, 0, 0, 0, 1, { 1, 1 }, { 0 }, { { 0 } }, 0,
	  { 0 }, { 0 }, { 0 }, 0 },
	{ "quilted_controls", "quilted control0 0.3 control1 0.9", 0, PATTERN_QUILTED, WAVE_RAMP, 0, 0, 0, 1,
	  { 0.3f, 0.9f }, { 0 }, { { 0 } }, 0, { 0 }, { 0 }, { 0.25f, 0.25f, 0.25f }, 0 },
	{ "radial", "radial frequency 3", 0, PATTERN_RADIAL, WAVE_RAMP, 0, 3, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 0 }, { -90, 0, 0 }, { 0 }, 0 },
	{ "ripples", "ripples", 0, PATTERN_RIPPLES, WAVE_RAMP, 0, 1, 0, 1, { 10 }, { 0 }, { { 0 } }, 0,
	  { 0 }, { 0 }, { 0 }, 0 },
	{ "ripples_frequency", "ripples frequency 2 phase 0.5", 0, PATTERN_RIPPLES, WAVE_RAMP, 0, 2, 0.5f, 1, { 10 },
	  { 0 }, { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
	{ "spherical", "spherical", 0, PATTERN_SPHERICAL, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 3, 3, 3 }, { 0 }, { 0 }, 0 },
	{ "spiral1", "spiral1 3 turbulence 0.2", 0, PATTERN_SPIRAL1, WAVE_TRIANGLE, 0, 1, 0, 1, { 3 }, { 0 },
	  { TURB(0.2f, 1) }, 1, { 0 }, { 0 }, { 0 }, 0 },
	{ "spiral2", "spiral2 5", 0, PATTERN_SPIRAL2, WAVE_TRIANGLE, 0, 1, 0, 1, { 5 }, { 0 }, { { 0 } }, 0,
	  { 2, 2, 2 }, { 0 }, { 0 }, 0 },
	{ "spotted", "spotted", 0, PATTERN_SPOTTED, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 0 }, { 0 }, { 0 }, 0 },
	{ "square", "square rgb 0, rgb 1/3, rgb 2/3, rgb 1", 4, PATTERN_SQUARE, WAVE_RAMP, 0, 0, 0, 1, { 0 }, { 0 },
	  { { 0 } }, 0, { 0.8f, 0.8f, 0.8f }, { -90, 0, 10 }, { 0 }, 0 },
	{ "triangular", "triangular rgb 0, rgb 0.2, rgb 0.4, rgb 0.6, rgb 0.8, rgb 1", 6, PATTERN_TRIANGULAR, WAVE_RAMP,
	  0, 0, 0, 1, { 0 }, { 0 }, { { 0 } }, 0, { 0 }, { -90, 0, 0 }, { 0 }, 0 },
	{ "waves", "waves", 0, PATTERN_WAVES, WAVE_RAMP, 0, 1, 0, 1, { 10 }, { 0 }, { { 0 } }, 0,
	  { 0 }, { 0 }, { 0 }, 0 },
	{ "waves_frequency", "waves frequency 0.5 phase 0.25", 0, PATTERN_WAVES, WAVE_RAMP, 0, 0.5f, 0.25f, 1, { 10 },
	  { 0 }, { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
	{ "wood", "wood turbulence 0.1", 0, PATTERN_WOOD, WAVE_TRIANGLE, 0, 1, 0, 1, { 0 }, { 0 },
	  { TURB(0.1f, 1) }, 1, { 0 }, { 0 }, { 0 }, 0 },
	{ "wood_ramp", "wood ramp_wave", 0, PATTERN_WOOD, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 0 }, { 0 }, { 0 }, 0 },
	{ "wrinkles", "wrinkles", 0, PATTERN_WRINKLES, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0,
	  { 0 }, { 0 }, { 0 }, 0 },
	{ "wrinkles_gen1", "wrinkles noise_generator 1", 0, PATTERN_WRINKLES, WAVE_RAMP, 1, 1, 0, 1, { 0 }, { 0 },
	  { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
	/* wave types, on a gradient three units wide */
	{ "wave_sine", "gradient x sine_wave", 0, PATTERN_GRADIENT, WAVE_SINE, 0, 1, 0, 1, { 1, 0, 0 }, { 0 },
	  { { 0 } }, 0, { 3, 3, 3 }, { 0 }, { 0 }, 0 },
	{ "wave_triangle", "gradient x triangle_wave", 0, PATTERN_GRADIENT, WAVE_TRIANGLE, 0, 1, 0, 1, { 1, 0, 0 },
	  { 0 }, { { 0 } }, 0, { 3, 3, 3 }, { 0 }, { 0 }, 0 },
	{ "wave_scallop", "gradient x scallop_wave", 0, PATTERN_GRADIENT, WAVE_SCALLOP, 0, 1, 0, 1, { 1, 0, 0 },
	  { 0 }, { { 0 } }, 0, { 3, 3, 3 }, { 0 }, { 0 }, 0 },
	{ "wave_cubic", "gradient x cubic_wave", 0, PATTERN_GRADIENT, WAVE_CUBIC, 0, 1, 0, 1, { 1, 0, 0 }, { 0 },
	  { { 0 } }, 0, { 3, 3, 3 }, { 0 }, { 0 }, 0 },
	{ "wave_poly", "gradient x poly_wave 2.5", 0, PATTERN_GRADIENT, WAVE_POLY, 0, 1, 0, 2.5f, { 1, 0, 0 }, { 0 },
	  { { 0 } }, 0, { 3, 3, 3 }, { 0 }, { 0 }, 0 },
	/* warps */
	{ "warp_repeat", "gradient y warp { repeat x * 1.5 offset <0, 0.3, 0> flip <0, 1, 0> }", 0, PATTERN_GRADIENT,
	  WAVE_RAMP, 0, 1, 0, 1, { 0, 1, 0 }, { 0 },
	  { { WARP_REPEAT, 0, { 1.5f, 0, 0 }, { 0, 0.3f, 0 }, { 0, 1, 0 } } }, 1, { 0 }, { 0 }, { 0 }, 0 },
	{ "warp_repeat_flip_axis", "gradient x warp { repeat y * 2 flip <0, 1, 0> }", 0, PATTERN_GRADIENT,
	  WAVE_RAMP, 0, 1, 0, 1, { 1, 0, 0 }, { 0 },
	  { { WARP_REPEAT, 0, { 0, 2, 0 }, { 0 }, { 0, 1, 0 } } }, 1, { 0 }, { 0 }, { 0 }, 0 },
	{ "warp_black_hole", "gradient x warp { black_hole <0.5, 0, 0>, 2.5 strength 1.5 falloff 1.5 }", 0,
	  PATTERN_GRADIENT, WAVE_RAMP, 0, 1, 0, 1, { 1, 0, 0 }, { 0 },
	  { { WARP_BLACK_HOLE, 0, { 0.5f, 0, 0, 2.5f }, { 1.5f, 1.5f, 0 }, { 0 } } }, 1,
	  { 3, 3, 3 }, { 0 }, { 0 }, 0 },
	{ "warp_black_hole_repeat", "gradient y warp { black_hole <0, 0, 0>, 1 inverse repeat <3, 2, 0> } ", 0,
	  PATTERN_GRADIENT, WAVE_RAMP, 0, 1, 0, 1, { 0, 1, 0 }, { 0 },
	  /* POV-Ray moves a repeated hole's centre to at least its radius */
	  { { WARP_BLACK_HOLE, 0, { 1, 1, 0, 1 }, { 1, 2, 1 }, { 3, 2, 0, 1 } } }, 1, { 0 }, { 0 }, { 0 }, 0 },
	{ "warps_chained", "bozo warp { repeat x * 2 } turbulence 0.4 warp { black_hole <0, 0, 0>, 3 }", 0,
	  PATTERN_BOZO, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 },
	  /* POV-Ray's order: warp { } to the front, the classic turbulence last */
	  { { WARP_BLACK_HOLE, 0, { 0, 0, 0, 3 }, { 1, 2, 0 }, { 0 } }, { WARP_REPEAT, 0, { 2, 0, 0 }, { 0 }, { 0 } },
	    TURB(0.4f, 1) }, 3, { 0 }, { 0 }, { 0 }, 0 },
	{ "marble_turbulence_repeat", "marble turbulence 0.5 warp { repeat x * 3 }", 0, PATTERN_MARBLE,
	  WAVE_TRIANGLE, 0, 1, 0, 1, { 0 }, { 0 }, { { WARP_REPEAT, 0, { 3, 0, 0 }, { 0 }, { 0 } }, TURB(0.5f, 1) }, 2,
	  { 0 }, { 0 }, { 0 }, 0 },
	/* scale 0.5 (written last) is the rows; scale 2, written before a warp, a warp */
	{ "warp_transform", "bozo warp { turbulence 0.5 } scale 2 warp { repeat x * 1.5 }", 0, PATTERN_BOZO,
	  WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 },
	  { { WARP_REPEAT, 0, { 1.5f, 0, 0 }, { 0 }, { 0 } },
	    { WARP_TRANSFORM, 0, { 0.5f, 0, 0, 0 }, { 0, 0.5f, 0, 0 }, { 0, 0, 0.5f, 0 } }, TURB(0.5f, 0) }, 3,
	  { 0.5f, 0.5f, 0.5f }, { 0 }, { 0 }, 0 },
	/* fractals (pattern_fractal.cl): at chaotic edges a point's escape depends on its
	 * last bits, and the device's point is a float where POV-Ray's is a double, so a
	 * few pixels may differ (the bound stays 99.5%); views where most pixels are
	 * chaotic (a magnet's large exterior values, wrapped) are left out */
	{ "mandel", "mandel 50", 0, PATTERN_MANDEL, WAVE_RAMP, 0, 1, 0, 1, { 50, 2, 0, 0 }, { 0, 1, 1, 1 }, { { 0 } }, 0,
	  { 1.5f, 1.5f, 1.5f }, { 0 }, { -0.8f, 0, 0 }, 0 },
	{ "mandel_exponent3", "mandel 40 exponent 3", 0, PATTERN_MANDEL, WAVE_RAMP, 0, 1, 0, 1, { 40, 3, 0, 0 }, { 0, 1, 1, 1 }, { { 0 } }, 0,
	  { 1.2f, 1.2f, 1.2f }, { 0 }, { 0, 0, 0 }, 0 },
	{ "mandel_exponent4", "mandel 30 exponent 4 interior 1, 1", 0, PATTERN_MANDEL, WAVE_RAMP, 0, 1, 0, 1, { 30, 4, 0, 0 }, { 1, 1, 1, 1 }, { { 0 } }, 0,
	  { 1.3f, 1.3f, 1.3f }, { 0 }, { 0, 0, 0 }, 0 },
	{ "mandel_exponent7", "mandel 25 exponent 7 exterior 6, 0.3", 0, PATTERN_MANDEL, WAVE_RAMP, 0, 1, 0, 1, { 25, 7, 0, 0 }, { 0, 1, 6, 0.3f }, { { 0 } }, 0,
	  { 1.3f, 1.3f, 1.3f }, { 0 }, { 0, 0, 0 }, 0 },
	{ "mandel_exterior7", "mandel 30 exterior 7, 5 interior 4, 2", 0, PATTERN_MANDEL, WAVE_RAMP, 0, 1, 0, 1, { 30, 2, 0, 0 }, { 4, 2, 7, 5 }, { { 0 } }, 0,
	  { 1.5f, 1.5f, 1.5f }, { 0 }, { -0.8f, 0, 0 }, 0 },
	{ "mandel_exterior8", "mandel 30 exterior 8, 4 interior 6, 0.5", 0, PATTERN_MANDEL, WAVE_RAMP, 0, 1, 0, 1, { 30, 2, 0, 0 }, { 6, 0.5f, 8, 4 }, { { 0 } }, 0,
	  { 1.5f, 1.5f, 1.5f }, { 0 }, { -0.8f, 0, 0 }, 0 },
	{ "julia", "julia <0.353, 0.288>, 60", 0, PATTERN_JULIA, WAVE_RAMP, 0, 1, 0, 1, { 60, 2, 0.353f, 0.288f }, { 0, 1, 1, 1 }, { { 0 } }, 0,
	  { 2, 2, 2 }, { 0 }, { 0, 0, 0 }, 0 },
	{ "julia_exponent3", "julia <-0.5, 0.5>, 40 exponent 3 interior 2, 1 exterior 2, 0.5", 0, PATTERN_JULIA, WAVE_RAMP, 0, 1, 0, 1, { 40, 3, -0.5f, 0.5f }, { 2, 1, 2, 0.5f }, { { 0 } }, 0,
	  { 2, 2, 2 }, { 0 }, { 0, 0, 0 }, 0 },
	{ "julia_exponent4", "julia <0.6, 0.2>, 30 exponent 4 interior 3, 1 exterior 3, 0.5", 0, PATTERN_JULIA, WAVE_RAMP, 0, 1, 0, 1, { 30, 4, 0.6f, 0.2f }, { 3, 1, 3, 0.5f }, { { 0 } }, 0,
	  { 2, 2, 2 }, { 0 }, { 0, 0, 0 }, 0 },
	{ "julia_exponent6", "julia <0.4, 0.3>, 30 exponent 6 interior 5, 2 exterior 5, 0.3", 0, PATTERN_JULIA, WAVE_RAMP, 0, 1, 0, 1, { 30, 6, 0.4f, 0.3f }, { 5, 2, 5, 0.3f }, { { 0 } }, 0,
	  { 2, 2, 2 }, { 0 }, { 0, 0, 0 }, 0 },
	{ "julia_frequency", "julia <0.353, 0.288>, 40 frequency 3 sine_wave exterior 0, 0.7", 0, PATTERN_JULIA, WAVE_SINE, 0, 3, 0, 1, { 40, 2, 0.353f, 0.288f }, { 0, 1, 0, 0.7f }, { { 0 } }, 0,
	  { 2, 2, 2 }, { 0 }, { 0, 0, 0 }, 0 },
	{ "magnet1_mandel", "magnet 1 mandel 12", 0, PATTERN_MAGNET, WAVE_RAMP, 0, 1, 0, 1, { 12, 1, 0, 0 }, { 0, 1, 1, 1 }, { { 0 } }, 0,
	  { 1.5f, 1.5f, 1.5f }, { 0 }, { 1, 0, 0 }, 0 },
	{ "magnet1_julia", "magnet 1 julia <0.3, 0.6>, 20", 0, PATTERN_MAGNET, WAVE_RAMP, 0, 1, 0, 1, { 20, 3, 0.3f, 0.6f }, { 0, 1, 1, 1 }, { { 0 } }, 0,
	  { 1.5f, 1.5f, 1.5f }, { 0 }, { 0, 0, 0 }, 0 },
	{ "magnet2_mandel", "magnet 2 mandel 30 interior 1, 0.5", 0, PATTERN_MAGNET, WAVE_RAMP, 0, 1, 0, 1, { 30, 2, 0, 0 }, { 1, 0.5f, 1, 1 }, { { 0 } }, 0,
	  { 1.5f, 1.5f, 1.5f }, { 0 }, { 1, 0, 0 }, 0 },
	{ "magnet2_julia", "magnet 2 julia <0.4, 0.3>, 30 interior 6, 0.5 exterior 6, 0.1", 0, PATTERN_MAGNET, WAVE_RAMP, 0, 1, 0, 1, { 30, 4, 0.4f, 0.3f }, { 6, 0.5f, 6, 0.1f }, { { 0 } }, 0,
	  { 1.5f, 1.5f, 1.5f }, { 0 }, { 0, 0, 0 }, 0 },
	{ "facets", NULL, 0, PATTERN_FACETS, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
	/* tilings (pattern_tiling.cl) of the x-z plane, turned to face the camera */
	{ "tiling1", "tiling 1", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 1 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling2", "tiling 2", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 2 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling3", "tiling 3", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 3 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling4", "tiling 4", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 4 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling5", "tiling 5", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 5 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling6", "tiling 6", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 6 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling7", "tiling 7", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 7 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling8", "tiling 8", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 8 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling9", "tiling 9", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 9 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling10", "tiling 10", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 10 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling11", "tiling 11", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 11 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling12", "tiling 12", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 12 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling13", "tiling 13", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 13 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling14", "tiling 14", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 14 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling15", "tiling 15", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 15 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling16", "tiling 16", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 16 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling17", "tiling 17", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 17 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling18", "tiling 18", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 18 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling19", "tiling 19", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 19 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling20", "tiling 20", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 20 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling21", "tiling 21", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 21 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling22", "tiling 22", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 22 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling23", "tiling 23", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 23 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling24", "tiling 24", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 24 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling25", "tiling 25", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 25 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling26", "tiling 26", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 26 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "tiling27", "tiling 27", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 27 }, { 0 }, { { 0 } }, 0,
	  { 0.7f, 0.7f, 0.7f }, { -90, 0, 0 }, { 0 }, 0 },
	/* far from the centre the Penrose tilings subdivide more: float against double */
	{ "tiling25_far", "tiling 25", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 25 }, { 0 }, { { 0 } }, 0,
	  { 0.1f, 0.1f, 0.1f }, { -90, 0, 0 }, { 30, 20, 0 }, 0 },
	{ "tiling26_far", "tiling 26", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 26 }, { 0 }, { { 0 } }, 0,
	  { 0.1f, 0.1f, 0.1f }, { -90, 0, 0 }, { 30, 20, 0 }, 0 },
	{ "tiling27_far", "tiling 27", 0, PATTERN_TILING, WAVE_RAMP, 0, 1, 0, 1, { 27 }, { 0 }, { { 0 } }, 0,
	  { 0.1f, 0.1f, 0.1f }, { -90, 0, 0 }, { 30, 20, 0 }, 0 },
	/* pavement (pattern_pavement.cl): the first and last pattern of each number of tiles and
	 * every fourth, with forms, interiors and exteriors in turn (all 112 pass; these keep
	 * make check short) */
	{ "pavement3_1_1", "pavement number_of_sides 3 number_of_tiles 1 pattern 1 form 0 interior 0 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 3, 1, 1, 0 }, { 0, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement3_2_1", "pavement number_of_sides 3 number_of_tiles 2 pattern 1 form 1 interior 0 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 3, 2, 1, 1 }, { 0, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement3_3_1", "pavement number_of_sides 3 number_of_tiles 3 pattern 1 form 2 interior 1 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 3, 3, 1, 2 }, { 1, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement3_4_1", "pavement number_of_sides 3 number_of_tiles 4 pattern 1 form 0 interior 1 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 3, 4, 1, 0 }, { 1, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement3_4_3", "pavement number_of_sides 3 number_of_tiles 4 pattern 3 form 2 interior 2 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 3, 4, 3, 2 }, { 2, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement3_5_1", "pavement number_of_sides 3 number_of_tiles 5 pattern 1 form 0 interior 0 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 3, 5, 1, 0 }, { 0, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement3_5_4", "pavement number_of_sides 3 number_of_tiles 5 pattern 4 form 0 interior 1 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 3, 5, 4, 0 }, { 1, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement3_6_1", "pavement number_of_sides 3 number_of_tiles 6 pattern 1 form 1 interior 2 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 3, 6, 1, 1 }, { 2, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement3_6_4", "pavement number_of_sides 3 number_of_tiles 6 pattern 4 form 1 interior 0 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 3, 6, 4, 1 }, { 0, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement3_6_8", "pavement number_of_sides 3 number_of_tiles 6 pattern 8 form 2 interior 2 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 3, 6, 8, 2 }, { 2, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement3_6_12", "pavement number_of_sides 3 number_of_tiles 6 pattern 12 form 0 interior 1 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 3, 6, 12, 0 }, { 1, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_1_1", "pavement number_of_sides 4 number_of_tiles 1 pattern 1 form 2 interior 2 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 1, 1, 2 }, { 2, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_2_1", "pavement number_of_sides 4 number_of_tiles 2 pattern 1 form 3 interior 2 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 2, 1, 3 }, { 2, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_3_1", "pavement number_of_sides 4 number_of_tiles 3 pattern 1 form 0 interior 0 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 3, 1, 0 }, { 0, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_3_2", "pavement number_of_sides 4 number_of_tiles 3 pattern 2 form 1 interior 0 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 3, 2, 1 }, { 0, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_4_1", "pavement number_of_sides 4 number_of_tiles 4 pattern 1 form 2 interior 1 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 4, 1, 2 }, { 1, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_4_4", "pavement number_of_sides 4 number_of_tiles 4 pattern 4 form 1 interior 2 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 4, 4, 1 }, { 2, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_4_5", "pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 2 interior 0 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 4, 5, 2 }, { 0, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_5_1", "pavement number_of_sides 4 number_of_tiles 5 pattern 1 form 3 interior 0 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 5, 1, 3 }, { 0, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_5_4", "pavement number_of_sides 4 number_of_tiles 5 pattern 4 form 2 interior 2 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 5, 4, 2 }, { 2, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_5_8", "pavement number_of_sides 4 number_of_tiles 5 pattern 8 form 2 interior 1 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 5, 8, 2 }, { 1, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_5_12", "pavement number_of_sides 4 number_of_tiles 5 pattern 12 form 2 interior 0 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 5, 12, 2 }, { 0, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_6_1", "pavement number_of_sides 4 number_of_tiles 6 pattern 1 form 3 interior 0 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 6, 1, 3 }, { 0, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_6_4", "pavement number_of_sides 4 number_of_tiles 6 pattern 4 form 2 interior 2 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 6, 4, 2 }, { 2, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_6_8", "pavement number_of_sides 4 number_of_tiles 6 pattern 8 form 2 interior 1 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 6, 8, 2 }, { 1, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_6_12", "pavement number_of_sides 4 number_of_tiles 6 pattern 12 form 2 interior 0 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 6, 12, 2 }, { 0, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_6_16", "pavement number_of_sides 4 number_of_tiles 6 pattern 16 form 2 interior 2 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 6, 16, 2 }, { 2, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_6_20", "pavement number_of_sides 4 number_of_tiles 6 pattern 20 form 2 interior 1 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 6, 20, 2 }, { 1, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_6_24", "pavement number_of_sides 4 number_of_tiles 6 pattern 24 form 2 interior 0 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 6, 24, 2 }, { 0, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_6_28", "pavement number_of_sides 4 number_of_tiles 6 pattern 28 form 2 interior 2 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 6, 28, 2 }, { 2, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_6_32", "pavement number_of_sides 4 number_of_tiles 6 pattern 32 form 2 interior 1 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 6, 32, 2 }, { 1, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement4_6_35", "pavement number_of_sides 4 number_of_tiles 6 pattern 35 form 1 interior 2 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 4, 6, 35, 1 }, { 2, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_1_1", "pavement number_of_sides 6 number_of_tiles 1 pattern 1 form 0 interior 0 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 1, 1, 0 }, { 0, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_2_1", "pavement number_of_sides 6 number_of_tiles 2 pattern 1 form 1 interior 0 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 2, 1, 1 }, { 0, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_3_1", "pavement number_of_sides 6 number_of_tiles 3 pattern 1 form 2 interior 1 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 3, 1, 2 }, { 1, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_3_3", "pavement number_of_sides 6 number_of_tiles 3 pattern 3 form 1 interior 2 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 3, 3, 1 }, { 2, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_4_1", "pavement number_of_sides 6 number_of_tiles 4 pattern 1 form 2 interior 2 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 4, 1, 2 }, { 2, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_4_4", "pavement number_of_sides 6 number_of_tiles 4 pattern 4 form 2 interior 1 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 4, 4, 2 }, { 1, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_4_7", "pavement number_of_sides 6 number_of_tiles 4 pattern 7 form 2 interior 2 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 4, 7, 2 }, { 2, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_5_1", "pavement number_of_sides 6 number_of_tiles 5 pattern 1 form 0 interior 0 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 5, 1, 0 }, { 0, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_5_4", "pavement number_of_sides 6 number_of_tiles 5 pattern 4 form 0 interior 1 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 5, 4, 0 }, { 1, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_5_8", "pavement number_of_sides 6 number_of_tiles 5 pattern 8 form 1 interior 0 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 5, 8, 1 }, { 0, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_5_12", "pavement number_of_sides 6 number_of_tiles 5 pattern 12 form 2 interior 2 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 5, 12, 2 }, { 2, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_5_16", "pavement number_of_sides 6 number_of_tiles 5 pattern 16 form 0 interior 1 exterior 2", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 5, 16, 0 }, { 1, 2 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_5_20", "pavement number_of_sides 6 number_of_tiles 5 pattern 20 form 1 interior 0 exterior 0", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 5, 20, 1 }, { 0, 0 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
	{ "pavement6_5_22", "pavement number_of_sides 6 number_of_tiles 5 pattern 22 form 0 interior 1 exterior 1", 0, PATTERN_PAVEMENT, WAVE_RAMP, 0, 1, 0, 1, { 6, 5, 22, 0 }, { 1, 1 },
	  { { 0 } }, 0, { 0.35f, 0.35f, 0.35f }, { -90, 0, 0 }, { 0 }, 0 },
};
#define N_CASES ((int)(sizeof cases / sizeof cases[0]))

/* ---- the scene and its camera ---- */

static void transform_text(const struct pcase *c, char *out, size_t n)
{
	out[0] = 0;
	if (c->scale[0] != 0)
		snprintf(out + strlen(out), n - strlen(out), " scale <%g, %g, %g>", c->scale[0], c->scale[1], c->scale[2]);
	if (c->rotate[0] != 0 || c->rotate[1] != 0 || c->rotate[2] != 0)
		snprintf(out + strlen(out), n - strlen(out), " rotate <%g, %g, %g>", c->rotate[0], c->rotate[1], c->rotate[2]);
	if (c->translate[0] != 0 || c->translate[1] != 0 || c->translate[2] != 0)
		snprintf(out + strlen(out), n - strlen(out), " translate <%g, %g, %g>", c->translate[0], c->translate[1],
		         c->translate[2]);
}

/* A case without POV-Ray's pattern has no scene. */
static int write_scene(const char *dir, int i, const char **name)
{
	const struct pcase *c = &cases[i];
	if (!c->pov)
		return 0;
	char xf[256];
	FILE *f = plane_scene_open(dir, c->name, c->perspective);
	if (!f)
		return -1;
	transform_text(c, xf, sizeof xf);
	fprintf(f, "plane { z, 0 pigment { %s%s%s } finish { ambient 1 diffuse 0 } }\n", c->pov,
	        c->list ? "" : " color_map { [0 rgb 0] [1 rgb 1] }", xf);
	*name = c->name;
	return fclose(f);
}

/* ---- the device ---- */

static const char *test_kernel =
	"kernel void pattern_test(global const dev_pattern *pt, global const dev_warp *warps,\n"
	"                         global const float4 *points, global const float4 *dirs, float4 normal,\n"
	"                         global float *out)\n"
	"{\n"
	"	int i = get_global_id(0);\n"
	"	scene_data sc = { 0 };   /* the buffers a pattern reads */\n"
	"	sc.warps = warps;\n"
	"	out[i] = pattern_value(&sc, pt, points[i].xyz, normal.xyz, dirs[i].xyz);\n"
	"}\n";

static const char *const kernel_files[] = { "kernels/shared.h", "kernels/intersect.cl", "kernels/function.cl", "kernels/scene.cl",
                                            "kernels/pattern_tables.cl", "kernels/pattern_fractal.cl", "kernels/pattern_tiling.cl", "kernels/pattern_pavement.cl", "kernels/pattern.cl" };

static void fill_pattern(const struct pcase *c, dev_pattern *pt, dev_warp *warps)
{
	plane_fill_pattern(pt, warps, c->kind, c->wave, c->gen, c->p0, c->p1, c->warps, c->n_warps);
	pt->frequency = c->freq;
	pt->phase = c->phase;
	pt->wave_exponent = c->exponent;
}

static int evaluate(struct plane_device *pd, const struct pcase *c, float *out)
{
	static float4 points[W * H], dirs[W * H];
	dev_pattern pt;
	dev_warp warps[PLANE_MAX_WARPS];
	fill_pattern(c, &pt, warps);
	for (int j = 0; j < H; j++)
		for (int i = 0; i < W; i++) {
			double p[3], dir[3];
			plane_camera_hit(c->perspective, i, j, p, dir);
			plane_to_pattern(c->scale, c->rotate, c->translate, p);
			points[j * W + i] = (float4){ (float)p[0], (float)p[1], (float)p[2], 0 };
			dirs[j * W + i] = (float4){ (float)dir[0], (float)dir[1], (float)dir[2], 0 };
		}
	/* The plane's normal as POV-Ray's aoi sees it: facing the camera. */
	float4 normal = { 0, 0, -1, 0 };
	const struct plane_arg args[] = {
		{ &pt, sizeof pt, 0 },
		{ warps, sizeof warps, 0 },
		{ points, sizeof points, 0 },
		{ dirs, sizeof dirs, 0 },
		{ &normal, sizeof normal, 1 },
	};
	return plane_run(pd, args, 5, out, W * H * sizeof(float));
}

static int compare(const char *dir)
{
	struct plane_device pd;
	if (plane_open(&pd, kernel_files, sizeof kernel_files / sizeof *kernel_files, test_kernel, "pattern_test", "test_pattern") != 0)
		return 1;
	int failures = 0;
	static float value[W * H], pov[W * H];
	for (int ci = 0; ci < N_CASES; ci++) {
		const struct pcase *c = &cases[ci];
		if (evaluate(&pd, c, value) != 0)
			return 1;
		if (!c->pov) {   /* no POV-Ray reference: a pigment of facets is 0 */
			int zeros = 0;
			for (int i = 0; i < W * H; i++)
				zeros += value[i] == 0.0f;
			int ok = zeros == W * H;
			printf("%s: %s: %d of %d pixels 0 (a normal-only pattern; POV-Ray has no pigment of it)\n",
			       ok ? "ok" : "FAIL", c->name, zeros, W * H);
			failures += !ok;
			continue;
		}
		if (plane_read_case(dir, c->name, pov, 1) != 0) {   /* red: all are equal */
			failures++;
			continue;
		}
		int within = 0, worst = 0;
		double max_diff = 0;
		for (int i = 0; i < W * H; i++) {
			double v = c->list ? value[i] / (c->list - 1) : value[i];
			v = v < 0 ? 0 : v > 1 ? 1 : v;
			double diff = fabs(v - pov[i]);
			within += diff <= 3.0 / 255;
			if (diff > max_diff)
				max_diff = diff, worst = i;
		}
		double share = 100.0 * within / (W * H);
		int ok = share >= 99.5;
		printf("%s: %s: %.2f%% of pixels within 3/255, largest difference %.4f at (%d, %d): %.4f, POV-Ray %.4f\n",
		       ok ? "ok" : "FAIL", c->name, share, max_diff, worst % W, worst / W,
		       c->list ? value[worst] / (c->list - 1) : value[worst], pov[worst]);
		failures += !ok;
	}
	plane_close(&pd);
	return failures != 0;
}

int main(int argc, char **argv)
{
	return plane_main(argc, argv, "test_pattern", N_CASES, write_scene, compare);
}
