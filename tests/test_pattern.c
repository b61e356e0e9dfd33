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

#include "device.h"
#include "shared.h"

#define W 160
#define H 120
#define MAX_WARPS 3

struct warp {
	int kind, classic;
	float a[4], b[4], c[4];
};

struct pcase {
	const char *name;
	const char *pov;       /* the pattern and its modifiers, inside pigment { } */
	int list;              /* discrete: the number of list entries; 0: a colour map */
	int kind, wave, gen;   /* gen 0: POV-Ray's default, 2 */
	float freq, phase, exponent;
	float p0[4], p1[4];
	struct warp warps[MAX_WARPS];
	int n_warps;
	float scale[3], rotate[3], translate[3];   /* written after the pattern; scale 0: none */
	int perspective;
};

/* The turbulence modifiers' defaults: octaves 6, omega 0.5, lambda 2. */
#define TURB(t, classic) { WARP_TURBULENCE, classic, { t, t, t, 0.5f }, { 2, 6 }, { 0 } }
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
	{ "facets", NULL, 0, PATTERN_FACETS, WAVE_RAMP, 0, 1, 0, 1, { 0 }, { 0 }, { { 0 } }, 0, { 0 }, { 0 }, { 0 }, 0 },
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

static int write_scene(const char *dir, const struct pcase *c)
{
	char path[4096], xf[256];
	snprintf(path, sizeof path, "%s/%s.pov", dir, c->name);
	FILE *f = fopen(path, "w");
	if (!f) {
		perror(path);
		return -1;
	}
	transform_text(c, xf, sizeof xf);
	fprintf(f, "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n");
	if (c->perspective)
		fprintf(f, "camera { perspective location <0, 0, -10> direction z right x * 4/3 up y }\n");
	else
		fprintf(f, "camera { orthographic location <0, 0, -10> look_at 0 right x * 8 up y * 6 }\n");
	fprintf(f, "plane { z, 0 pigment { %s%s%s } finish { ambient 1 diffuse 0 } }\n", c->pov,
	        c->list ? "" : " color_map { [0 rgb 0] [1 rgb 1] }", xf);
	return fclose(f);
}

/* The point on the plane z = 0 seen through pixel (i, j)'s centre, and the
 * ray's direction. */
static void camera_hit(const struct pcase *c, int i, int j, double p[3], double d[3])
{
	double sx = (i + 0.5) / W - 0.5, sy = 0.5 - (j + 0.5) / H;
	if (c->perspective) {
		d[0] = sx * 4.0 / 3.0, d[1] = sy, d[2] = 1;
		double len = sqrt(d[0] * d[0] + d[1] * d[1] + 1);
		p[0] = 10 * d[0], p[1] = 10 * d[1], p[2] = 0;
		for (int k = 0; k < 3; k++)
			d[k] /= len;
	} else {
		p[0] = sx * 8, p[1] = sy * 6, p[2] = 0;
		d[0] = 0, d[1] = 0, d[2] = 1;
	}
}

static void rotate_axis(double p[3], int axis, double degrees)
{
	double a = degrees * M_PI / 180, cs = cos(a), sn = sin(a);
	int u = (axis + 1) % 3, v = (axis + 2) % 3;
	double pu = p[u] * cs - p[v] * sn, pv = p[u] * sn + p[v] * cs;
	p[u] = pu, p[v] = pv;
}

/* World to the pattern's space: POV-Ray's scale, rotate (x, then y, then z)
 * and translate, undone in reverse order. */
static void to_pattern(const struct pcase *c, double p[3])
{
	for (int k = 0; k < 3; k++)
		p[k] -= c->translate[k];
	for (int axis = 2; axis >= 0; axis--)
		if (c->rotate[axis] != 0)
			rotate_axis(p, axis, -c->rotate[axis]);
	if (c->scale[0] != 0)
		for (int k = 0; k < 3; k++)
			p[k] /= c->scale[k];
}

/* ---- POV-Ray's image: a binary PPM, 16 bits a channel ---- */

static int ppm_token(FILE *f)
{
	int ch;
	for (;;) {
		ch = getc(f);
		if (ch == '#')
			while (ch != '\n' && ch != EOF)
				ch = getc(f);
		else if (ch != ' ' && ch != '\t' && ch != '\n' && ch != '\r')
			break;
	}
	int v = 0;
	while (ch >= '0' && ch <= '9') {
		v = v * 10 + (ch - '0');
		ch = getc(f);
	}
	return v;
}

static int read_ppm(const char *path, float *grey)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return -1;
	int ok = getc(f) == 'P' && getc(f) == '6';
	int w = ppm_token(f), h = ppm_token(f), max = ppm_token(f);
	ok = ok && w == W && h == H && max > 0;
	for (int i = 0; ok && i < W * H; i++) {
		unsigned char px[6];
		int bytes = max > 255 ? 6 : 3;
		if (fread(px, 1, bytes, f) != (size_t)bytes)
			ok = 0;
		else
			grey[i] = (bytes == 6 ? px[0] << 8 | px[1] : px[0]) / (float)max;   /* red: all are equal */
	}
	fclose(f);
	return ok ? 0 : -1;
}

/* ---- the device ---- */

static const char *test_kernel =
	"kernel void pattern_test(global const dev_pattern *pt, global const dev_warp *warps,\n"
	"                         global const float4 *points, global const float4 *dirs, float4 normal,\n"
	"                         global float *out)\n"
	"{\n"
	"	int i = get_global_id(0);\n"
	"	out[i] = pattern_value(pt, warps, points[i].xyz, normal.xyz, dirs[i].xyz);\n"
	"}\n";

static cl_program build(device_ctx *d)
{
	const char *texts[8];
	int n = 0;
	for (int i = 0; device_sources[i].name; i++)
		if (!strcmp(device_sources[i].name, "kernels/shared.h") ||
		    !strcmp(device_sources[i].name, "kernels/pattern_tables.cl") ||
		    !strcmp(device_sources[i].name, "kernels/pattern.cl"))
			texts[n++] = device_sources[i].text;
	if (n != 3) {
		fprintf(stderr, "test_pattern: the embedded kernels lack pattern.cl or its tables\n");
		return NULL;
	}
	texts[n++] = test_kernel;
	cl_int err;
	cl_program prog = clCreateProgramWithSource(d->context, n, texts, NULL, &err);
	if (!prog) {
		device_fail("clCreateProgramWithSource", err);
		return NULL;
	}
	err = clBuildProgram(prog, 1, &d->device, "-cl-std=CL1.2", NULL, NULL);
	if (err != CL_SUCCESS) {
		char log[16384];
		clGetProgramBuildInfo(prog, d->device, CL_PROGRAM_BUILD_LOG, sizeof log, log, NULL);
		fprintf(stderr, "test_pattern: build failed:\n%s\n", log);
		clReleaseProgram(prog);
		return NULL;
	}
	return prog;
}

static void fill_pattern(const struct pcase *c, dev_pattern *pt, dev_warp *warps)
{
	memset(pt, 0, sizeof *pt);
	pt->kind = c->kind;
	pt->wave = c->wave;
	pt->noise_generator = c->gen ? c->gen : 2;
	pt->frequency = c->freq;
	pt->phase = c->phase;
	pt->wave_exponent = c->exponent;
	memcpy(&pt->params[0], c->p0, sizeof c->p0);
	memcpy(&pt->params[1], c->p1, sizeof c->p1);
	if (c->kind == PATTERN_GRADIENT) {   /* POV-Ray normalizes the axis */
		float *a = &pt->params[0].x;
		float len = sqrtf(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
		for (int k = 0; k < 3; k++)
			a[k] /= len;
	}
	pt->warp_first = 0;
	pt->warp_count = c->n_warps;
	memset(warps, 0, MAX_WARPS * sizeof *warps);
	for (int i = 0; i < c->n_warps; i++) {
		warps[i].kind = c->warps[i].kind;
		warps[i].classic = c->warps[i].classic;
		memcpy(&warps[i].a, c->warps[i].a, sizeof warps[i].a);
		memcpy(&warps[i].b, c->warps[i].b, sizeof warps[i].b);
		memcpy(&warps[i].c, c->warps[i].c, sizeof warps[i].c);
	}
}

static int evaluate(device_ctx *d, cl_kernel k, const struct pcase *c, float *out)
{
	static float4 points[W * H], dirs[W * H];
	dev_pattern pt;
	dev_warp warps[MAX_WARPS];
	fill_pattern(c, &pt, warps);
	for (int j = 0; j < H; j++)
		for (int i = 0; i < W; i++) {
			double p[3], dir[3];
			camera_hit(c, i, j, p, dir);
			to_pattern(c, p);
			points[j * W + i] = (float4){ (float)p[0], (float)p[1], (float)p[2], 0 };
			dirs[j * W + i] = (float4){ (float)dir[0], (float)dir[1], (float)dir[2], 0 };
		}
	/* The plane's normal as POV-Ray's aoi sees it: facing the camera. */
	float4 normal = { 0, 0, -1, 0 };
	cl_int err;
	cl_mem bp = clCreateBuffer(d->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof pt, &pt, &err);
	cl_mem bw = clCreateBuffer(d->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof warps, warps, &err);
	cl_mem bpts = clCreateBuffer(d->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof points, points, &err);
	cl_mem bdir = clCreateBuffer(d->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof dirs, dirs, &err);
	cl_mem bout = clCreateBuffer(d->context, CL_MEM_WRITE_ONLY, W * H * sizeof(float), NULL, &err);
	if (!bp || !bw || !bpts || !bdir || !bout)
		return device_fail("clCreateBuffer", err);
	clSetKernelArg(k, 0, sizeof bp, &bp);
	clSetKernelArg(k, 1, sizeof bw, &bw);
	clSetKernelArg(k, 2, sizeof bpts, &bpts);
	clSetKernelArg(k, 3, sizeof bdir, &bdir);
	clSetKernelArg(k, 4, sizeof normal, &normal);
	clSetKernelArg(k, 5, sizeof bout, &bout);
	size_t global = W * H;
	err = clEnqueueNDRangeKernel(d->queue, k, 1, NULL, &global, NULL, 0, NULL, NULL);
	if (err == CL_SUCCESS)
		err = clEnqueueReadBuffer(d->queue, bout, CL_TRUE, 0, W * H * sizeof(float), out, 0, NULL, NULL);
	clReleaseMemObject(bp);
	clReleaseMemObject(bw);
	clReleaseMemObject(bpts);
	clReleaseMemObject(bdir);
	clReleaseMemObject(bout);
	return err == CL_SUCCESS ? 0 : device_fail("pattern_test", err);
}

static int compare(const char *dir)
{
	device_ctx d;
	if (device_open(&d, -1) != 0)
		return 1;
	cl_program prog = build(&d);
	if (!prog)
		return 1;
	cl_int err;
	cl_kernel k = clCreateKernel(prog, "pattern_test", &err);
	if (!k)
		return device_fail("clCreateKernel", err) ? 1 : 1;
	int failures = 0;
	static float value[W * H], pov[W * H];
	for (int ci = 0; ci < N_CASES; ci++) {
		const struct pcase *c = &cases[ci];
		if (evaluate(&d, k, c, value) != 0)
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
		char path[4096];
		snprintf(path, sizeof path, "%s/%s.ppm", dir, c->name);
		if (read_ppm(path, pov) != 0) {
			printf("FAIL: %s: no image from POV-Ray (%s)\n", c->name, path);
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
	clReleaseKernel(k);
	clReleaseProgram(prog);
	device_close(&d);
	return failures != 0;
}

int main(int argc, char **argv)
{
	if (argc == 3 && !strcmp(argv[1], "write")) {
		char path[4096];
		snprintf(path, sizeof path, "%s/cases", argv[2]);
		FILE *list = fopen(path, "w");
		if (!list) {
			perror(path);
			return 1;
		}
		for (int i = 0; i < N_CASES; i++)
			if (cases[i].pov) {
				if (write_scene(argv[2], &cases[i]) != 0)
					return 1;
				fprintf(list, "%s\n", cases[i].name);
			}
		return fclose(list) != 0;
	}
	if (argc == 3 && !strcmp(argv[1], "compare"))
		return compare(argv[2]);
	fprintf(stderr, "usage: test_pattern write|compare DIR\n");
	return 2;
}
