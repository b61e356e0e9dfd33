/* test_normal.c: kernels/normal.cl's pattern_perturb against POV-Ray 3.7 itself.
 *
 *   test_normal write DIR     writes DIR/NAME.pov for every case and the list DIR/cases
 *   test_normal compare DIR   reads POV-Ray's DIR/NAME.ppm (16-bit, linear) and
 *                             compares them with pattern_perturb, one line a case
 *
 * Each case is a white plane z = 0 with a normal { } seen by an orthographic
 * camera from z = -10, lit by three parallel shadowless lights and nothing
 * else: a red one from <1, 0, -1>, a green one from <0, 1, -1>, a blue one from
 * <0, 0, -1>, with ambient 0, diffuse 1 and brilliance 1, so that POV-Ray's
 * pixel is max(0, N.L) of each light in its own channel. tests/normal.test
 * renders the scenes with povray between the two steps. The program evaluates
 * pattern_perturb at each pixel's point on the plane (the normal <0, 0, -1>,
 * facing the camera), through the embedded kernels/shared.h,
 * pattern_tables.cl, pattern.cl and normal.cl and a kernel of its own, turns
 * the normal into the same colour, and compares. A case passes when at least
 * 99.5% of the pixels are within 3/255 of POV-Ray's in every channel. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "povray_plane.h"

#define W PLANE_W
#define H PLANE_H
#define MAX_SLOPES 4

struct ncase {
	const char *name;
	const char *pov;        /* the pattern and its modifiers, inside normal { } */
	int kind, wave, gen;    /* gen 0: POV-Ray's default, 2 */
	float freq, phase;      /* freq 0: 1 (POV-Ray's default) */
	float amount, accuracy; /* 0: POV-Ray's defaults, 0.5 and 0.02 */
	float p0[4], p1[4];
	struct plane_warp warps[PLANE_MAX_WARPS];
	int n_warps;
	float scale[3], rotate[3], translate[3];   /* written after the pattern; scale 0: none */
	float slopes[MAX_SLOPES][3];                /* slope_map: value, height, slope */
	int n_slopes, flags;
};

#define TURB(t, classic) PLANE_TURB(t, classic)

static const struct ncase cases[] = {
	/* POV-Ray's own normal functions */
	{ .name = "bumps", .pov = "bumps scale 0.5", .kind = PATTERN_BUMPS, .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "bumps_negative", .pov = "bumps -0.8 scale 0.5", .kind = PATTERN_BUMPS, .amount = -0.8f, .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "bumps_transformed", .pov = "bumps 0.7 scale <0.5, 1, 0.3> rotate <20, 30, 40> translate <0.3, 0.1, 0>",
	  .kind = PATTERN_BUMPS, .amount = 0.7f, .scale = { 0.5f, 1, 0.3f }, .rotate = { 20, 30, 40 },
	  .translate = { 0.3f, 0.1f, 0 } },
	{ .name = "bumps_no_bump_scale", .pov = "bumps 0.5 scale 0.4 no_bump_scale", .kind = PATTERN_BUMPS,
	  .scale = { 0.4f, 0.4f, 0.4f }, .flags = PATTERN_NO_BUMP_SCALE },
	/* scale 0.5 before the warp is a warp of its own; 0.7, written last, the rows */
	{ .name = "bumps_warp_transform", .pov = "bumps 0.6 scale 0.5 warp { turbulence 0.3 } scale 0.7", .kind = PATTERN_BUMPS,
	  .amount = 0.6f, .warps = { TURB(0.3f, 0), { WARP_TRANSFORM, 0, { 2, 0, 0, 0 }, { 0, 2, 0, 0 }, { 0, 0, 2, 0 } } },
	  .n_warps = 2, .scale = { 0.7f, 0.7f, 0.7f } },
	{ .name = "dents", .pov = "dents 1 scale 0.5", .kind = PATTERN_DENTS, .amount = 1, .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "dents_gen1", .pov = "dents 1.5 noise_generator 1 scale 0.5", .kind = PATTERN_DENTS, .gen = 1, .amount = 1.5f,
	  .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "dents_gen3", .pov = "dents 1.5 noise_generator 3 scale 0.5", .kind = PATTERN_DENTS, .gen = 3, .amount = 1.5f,
	  .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "ripples", .pov = "ripples 0.5", .kind = PATTERN_RIPPLES, .p0 = { 10 } },
	/* fractals, tilting the normal by their slope */
	{ .name = "mandel", .pov = "mandel 30 0.6 scale 2", .kind = PATTERN_MANDEL, .amount = 0.6f,
	  .p0 = { 30, 2, 0, 0 }, .p1 = { 0, 1, 1, 1 }, .scale = { 2, 2, 2 } },
	{ .name = "julia_exterior", .pov = "julia <0.353, 0.288>, 20 0.8 exterior 6, 0.3 scale 2", .kind = PATTERN_JULIA,
	  .amount = 0.8f, .p0 = { 20, 2, 0.353f, 0.288f }, .p1 = { 0, 1, 6, 0.3f }, .scale = { 2, 2, 2 } },
	{ .name = "ripples_frequency", .pov = "ripples 0.6 frequency 3 phase 0.2", .kind = PATTERN_RIPPLES, .freq = 3, .phase = 0.2f,
	  .amount = 0.6f, .p0 = { 10 } },
	{ .name = "waves", .pov = "waves 0.5", .kind = PATTERN_WAVES, .p0 = { 10 } },
	{ .name = "waves_frequency", .pov = "waves 0.4 frequency 2 phase 0.3 rotate 30*z", .kind = PATTERN_WAVES, .freq = 2, .phase = 0.3f,
	  .amount = 0.4f, .p0 = { 10 }, .rotate = { 0, 0, 30 } },
	{ .name = "wrinkles", .pov = "wrinkles 0.6 scale 0.5", .kind = PATTERN_WRINKLES, .amount = 0.6f, .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "quilted", .pov = "quilted 0.6 control0 0.3 control1 0.9 scale 0.7", .kind = PATTERN_QUILTED, .amount = 0.6f,
	  .p0 = { 0.3f, 0.9f }, .scale = { 0.7f, 0.7f, 0.7f } },
	{ .name = "facets", .pov = "facets size 0.3", .kind = PATTERN_FACETS, .p0 = { 0.3f, 0, 2 } },
	{ .name = "facets_coords", .pov = "facets coords 0.6 scale 0.8", .kind = PATTERN_FACETS, .p0 = { 0.1f, 0.6f, 2 },
	  .scale = { 0.8f, 0.8f, 0.8f } },
	{ .name = "facets_metric", .pov = "facets coords 1 size 0.5 metric 3", .kind = PATTERN_FACETS, .p0 = { 0.5f, 1, 3 } },
	/* the slope of the pattern's value, POV-Ray's pyramid of four points */
	{ .name = "gradient", .pov = "gradient x 0.5 scale 2", .kind = PATTERN_GRADIENT, .p0 = { 1, 0, 0 }, .scale = { 2, 2, 2 } },
	{ .name = "gradient_wave", .pov = "gradient <1, 2, 0> 0.5 frequency 2 phase 0.3 sine_wave scale 3", .kind = PATTERN_GRADIENT,
	  .wave = WAVE_SINE, .freq = 2, .phase = 0.3f, .p0 = { 1, 2, 0 }, .scale = { 3, 3, 3 } },
	{ .name = "checker", .pov = "checker 0.5 scale 0.7 translate <0.11, 0.23, 0>", .kind = PATTERN_CHECKER,
	  .scale = { 0.7f, 0.7f, 0.7f }, .translate = { 0.11f, 0.23f, 0 } },
	{ .name = "cells", .pov = "cells 0.3 scale 0.7", .kind = PATTERN_CELLS, .amount = 0.3f, .scale = { 0.7f, 0.7f, 0.7f } },
	{ .name = "bozo", .pov = "bozo 1 scale 0.5", .kind = PATTERN_BOZO, .amount = 1, .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "bozo_gen1", .pov = "bozo 1 noise_generator 1 scale 0.5", .kind = PATTERN_BOZO, .gen = 1, .amount = 1, .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "bozo_gen3", .pov = "bozo 1 noise_generator 3 scale 0.5", .kind = PATTERN_BOZO, .gen = 3, .amount = 1, .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "bozo_bump_size", .pov = "bozo bump_size 1.5 scale 0.5", .kind = PATTERN_BOZO, .amount = 1.5f,
	  .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "bozo_accuracy", .pov = "bozo 1 accuracy 0.005 scale 0.5", .kind = PATTERN_BOZO, .amount = 1, .accuracy = 0.005f,
	  .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "bozo_turbulence", .pov = "bozo 1.2 turbulence 0.4 scale 0.5", .kind = PATTERN_BOZO, .amount = 1.2f,
	  .warps = { TURB(0.4f, 1) }, .n_warps = 1, .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "bozo_warp_repeat", .pov = "bozo 1.2 warp { repeat x * 1.5 flip y } scale 0.5", .kind = PATTERN_BOZO, .amount = 1.2f,
	  .warps = { { WARP_REPEAT, 0, { 1.5f, 0, 0 }, { 0 }, { 0, 1, 0 } } }, .n_warps = 1,
	  .scale = { 0.5f, 0.5f, 0.5f } },
	/* tilings of the x-z plane, turned to face the camera */
	{ .name = "tiling2", .pov = "tiling 2 0.5 scale 0.7 rotate -90*x", .kind = PATTERN_TILING, .p0 = { 2 },
	  .scale = { 0.7f, 0.7f, 0.7f }, .rotate = { -90, 0, 0 } },
	{ .name = "tiling16", .pov = "tiling 16 bump_size 0.8 scale 0.7 rotate -90*x", .kind = PATTERN_TILING, .amount = 0.8f,
	  .p0 = { 16 }, .scale = { 0.7f, 0.7f, 0.7f }, .rotate = { -90, 0, 0 } },
	{ .name = "tiling26", .pov = "tiling 26 0.6 scale 0.7 rotate -90*x", .kind = PATTERN_TILING, .amount = 0.6f,
	  .p0 = { 26 }, .scale = { 0.7f, 0.7f, 0.7f }, .rotate = { -90, 0, 0 } },
	{ .name = "pavement4", .pov = "pavement 0.6 number_of_sides 4 number_of_tiles 4 pattern 3 form 2 interior 2 exterior 2 scale 0.5 rotate -90*x",
	  .kind = PATTERN_PAVEMENT, .amount = 0.6f, .p0 = { 4, 4, 3, 2 }, .p1 = { 2, 2 }, .scale = { 0.5f, 0.5f, 0.5f },
	  .rotate = { -90, 0, 0 } },
	{ .name = "pavement6", .pov = "pavement 0.5 number_of_sides 6 number_of_tiles 3 pattern 2 form 1 interior 1 scale 0.4 rotate -90*x",
	  .kind = PATTERN_PAVEMENT, .p0 = { 6, 3, 2, 1 }, .p1 = { 1, 0 }, .scale = { 0.4f, 0.4f, 0.4f }, .rotate = { -90, 0, 0 } },
	{ .name = "granite", .pov = "granite 0.3 scale 2", .kind = PATTERN_GRANITE, .amount = 0.3f, .scale = { 2, 2, 2 } },
	{ .name = "granite_negative", .pov = "granite -0.4 scale 2", .kind = PATTERN_GRANITE, .amount = -0.4f, .scale = { 2, 2, 2 } },
	{ .name = "crackle", .pov = "crackle 1 scale 0.5", .kind = PATTERN_CRACKLE, .amount = 1, .p0 = { -1, 1, 0, 2 }, .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "marble", .pov = "marble 0.5 turbulence 0.5", .kind = PATTERN_MARBLE, .wave = WAVE_TRIANGLE, .warps = { TURB(0.5f, 1) },
	  .n_warps = 1 },
	{ .name = "wood", .pov = "wood 0.5 turbulence 0.1 scale 0.5", .kind = PATTERN_WOOD, .wave = WAVE_TRIANGLE,
	  .warps = { TURB(0.1f, 1) }, .n_warps = 1, .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "agate", .pov = "agate 0.5 scale 0.5", .kind = PATTERN_AGATE, .p0 = { 1 }, .warps = { TURB(0, 1) }, .n_warps = 1,
	  .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "leopard", .pov = "leopard 1 scale 0.3", .kind = PATTERN_LEOPARD, .amount = 1, .scale = { 0.3f, 0.3f, 0.3f } },
	{ .name = "onion", .pov = "onion 0.5 scale 0.7", .kind = PATTERN_ONION, .scale = { 0.7f, 0.7f, 0.7f } },
	{ .name = "onion_scallop", .pov = "onion 0.5 frequency 2 phase 0.3 scallop_wave scale 2", .kind = PATTERN_ONION,
	  .wave = WAVE_SCALLOP, .freq = 2, .phase = 0.3f, .scale = { 2, 2, 2 } },
	{ .name = "spiral1", .pov = "spiral1 3, 0.5 turbulence 0.2", .kind = PATTERN_SPIRAL1, .wave = WAVE_TRIANGLE, .p0 = { 3 },
	  .warps = { TURB(0.2f, 1) }, .n_warps = 1 },
	{ .name = "brick", .pov = "brick 0.5 scale 0.25", .kind = PATTERN_BRICK, .p0 = { 8, 3, 4.5f, 0.5f },
	  .scale = { 0.25f, 0.25f, 0.25f } },
	{ .name = "hexagon", .pov = "hexagon 0.5 scale 0.5 rotate -80*x", .kind = PATTERN_HEXAGON,
	  .scale = { 0.5f, 0.5f, 0.5f }, .rotate = { -80, 0, 0 } },
	{ .name = "radial", .pov = "radial 0.8 frequency 4 rotate -90*x", .kind = PATTERN_RADIAL, .amount = 0.8f,
	  .freq = 4, .rotate = { -90, 0, 0 } },
	{ .name = "spherical", .pov = "spherical 1 scale 3", .kind = PATTERN_SPHERICAL, .amount = 1,
	  .scale = { 3, 3, 3 } },
	{ .name = "spotted", .pov = "spotted 1 scale 0.5", .kind = PATTERN_SPOTTED, .amount = 1,
	  .scale = { 0.5f, 0.5f, 0.5f } },
	{ .name = "wrinkles_gen3", .pov = "wrinkles 1 noise_generator 3 scale 0.3", .kind = PATTERN_WRINKLES,
	  .gen = 3, .amount = 1, .scale = { 0.3f, 0.3f, 0.3f } },
	{ .name = "aoi", .pov = "aoi 0.5", .kind = PATTERN_AOI },
	{ .name = "slope_map", .pov = "gradient x 0.5 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } scale 2", .kind = PATTERN_GRADIENT,
	  .p0 = { 1, 0, 0 }, .scale = { 2, 2, 2 }, .slopes = { { 0, 0, 1 }, { 0.5f, 1, 0 }, { 1, 0, -1 } }, .n_slopes = 3 },
	{ .name = "slope_map_bozo", .pov = "bozo 1 slope_map { [0 <0, 0>] [0.4 <0.2, 2>] [0.6 <0.8, 2>] [1 <1, 0>] } scale 0.5",
	  .kind = PATTERN_BOZO, .amount = 1, .scale = { 0.5f, 0.5f, 0.5f },
	  .slopes = { { 0, 0, 0 }, { 0.4f, 0.2f, 2 }, { 0.6f, 0.8f, 2 }, { 1, 1, 0 } }, .n_slopes = 4 },
};
#define N_CASES ((int)(sizeof cases / sizeof cases[0]))

/* The lights, from the surface towards each, and their colours' channels. */
static const double light_dir[3][3] = { { 1, 0, -1 }, { 0, 1, -1 }, { 0, 0, -1 } };

/* ---- the scene ---- */

static int write_scene(const char *dir, int i, const char **name)
{
	const struct ncase *c = &cases[i];
	FILE *f = plane_scene_open(dir, c->name, 0);
	if (!f)
		return -1;
	static const char *colours[3] = { "<1, 0, 0>", "<0, 1, 0>", "<0, 0, 1>" };
	for (int k = 0; k < 3; k++)
		fprintf(f, "light_source { <%g, %g, %g> color rgb %s parallel point_at <0, 0, 0> shadowless }\n",
		        10 * light_dir[k][0], 10 * light_dir[k][1], 10 * light_dir[k][2], colours[k]);
	fprintf(f, "plane { z, 0 texture { pigment { rgb 1 } normal { %s } finish { ambient 0 diffuse 1 } } }\n",
	        c->pov);
	*name = c->name;
	return fclose(f);
}

/* ---- the device ---- */

static const char *test_kernel =
	"kernel void normal_test(global const dev_pattern *pt, global const dev_warp *warps,\n"
	"                        global const dev_map_entry *maps, global const float4 *points,\n"
	"                        global float4 *out)\n"
	"{\n"
	"	int i = get_global_id(0);\n"
	"	scene_data sc = { 0 };   /* the buffers a normal reads */\n"
	"	sc.warps = warps;\n"
	"	sc.maps = maps;\n"
	"	out[i] = (float4)(pattern_perturb(&sc, pt, points[i].xyz, (float3)(0.0f, 0.0f, -1.0f)), 0.0f);\n"
	"}\n";

static const char *const kernel_files[] = { "kernels/shared.h", "kernels/intersect.cl", "kernels/function.cl", "kernels/scene.cl",
                                            "kernels/pattern_tables.cl", "kernels/pattern_fractal.cl", "kernels/pattern_tiling.cl", "kernels/pattern_pavement.cl", "kernels/pattern.cl",
                                            "kernels/normal.cl" };

static void fill_pattern(const struct ncase *c, dev_pattern *pt, dev_warp *warps, dev_map_entry *maps)
{
	plane_fill_pattern(pt, warps, c->kind, c->wave, c->gen, c->p0, c->p1, c->warps, c->n_warps);
	pt->frequency = c->freq != 0 ? c->freq : 1;
	pt->phase = c->phase;
	pt->wave_exponent = 1;
	pt->bump_size = c->amount != 0 ? c->amount : 0.5f;
	pt->normal.x = c->accuracy != 0 ? c->accuracy : 0.02f;
	pt->flags = c->flags;
	/* rows: world to the pattern's space, column by column */
	double o[3] = { 0, 0, 0 };
	plane_to_pattern(c->scale, c->rotate, c->translate, o);
	float *rows[3] = { &pt->rows[0].x, &pt->rows[1].x, &pt->rows[2].x };
	for (int j = 0; j < 3; j++) {
		double e[3] = { 0, 0, 0 };
		e[j] = 1;
		plane_to_pattern(c->scale, c->rotate, NULL, e);
		for (int k = 0; k < 3; k++)
			rows[k][j] = (float)e[k];
	}
	for (int k = 0; k < 3; k++)
		rows[k][3] = (float)o[k];
	pt->map_first = 0;
	pt->map_count = c->n_slopes;
	memset(maps, 0, MAX_SLOPES * sizeof *maps);
	for (int i = 0; i < c->n_slopes; i++) {
		maps[i].value = c->slopes[i][0];
		maps[i].colour.x = c->slopes[i][1];
		maps[i].colour.y = c->slopes[i][2];
		maps[i].pigment = -1;
	}
}

static int evaluate(struct plane_device *pd, const struct ncase *c, float4 *out)
{
	static float4 points[W * H];
	dev_pattern pt;
	dev_warp warps[PLANE_MAX_WARPS];
	dev_map_entry maps[MAX_SLOPES];
	fill_pattern(c, &pt, warps, maps);
	for (int j = 0; j < H; j++)
		for (int i = 0; i < W; i++) {
			double p[3], dir[3];
			plane_camera_hit(0, i, j, p, dir);
			points[j * W + i] = (float4){ (float)p[0], (float)p[1], (float)p[2], 0 };
		}
	const struct plane_arg args[] = {
		{ &pt, sizeof pt, 0 },
		{ warps, sizeof warps, 0 },
		{ maps, sizeof maps, 0 },
		{ points, sizeof points, 0 },
	};
	return plane_run(pd, args, 4, out, W * H * sizeof(float4));
}

/* POV-Ray's diffuse from the three lights: max(0, N.L), one light a channel. */
static void shade(float4 n, double rgb[3])
{
	for (int k = 0; k < 3; k++) {
		const double *l = light_dir[k];
		double len = sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
		double c = (n.x * l[0] + n.y * l[1] + n.z * l[2]) / len;
		rgb[k] = c > 0 ? c : 0;
	}
}

static int compare(const char *dir)
{
	struct plane_device pd;
	if (plane_open(&pd, kernel_files, sizeof kernel_files / sizeof *kernel_files, test_kernel, "normal_test", "test_normal") != 0)
		return 1;
	int failures = 0;
	static float4 normal[W * H];
	static float pov[3 * W * H];
	for (int ci = 0; ci < N_CASES; ci++) {
		const struct ncase *c = &cases[ci];
		if (evaluate(&pd, c, normal) != 0)
			return 1;
		if (plane_read_case(dir, c->name, pov, 3) != 0) {
			failures++;
			continue;
		}
		int within = 0, worst = 0;
		double max_diff = 0, worst_rgb[3] = { 0 };
		for (int i = 0; i < W * H; i++) {
			double rgb[3], diff = 0;
			shade(normal[i], rgb);
			for (int ch = 0; ch < 3; ch++)
				diff = fmax(diff, fabs(rgb[ch] - pov[3 * i + ch]));
			within += diff <= 3.0 / 255;
			if (diff > max_diff) {
				max_diff = diff, worst = i;
				memcpy(worst_rgb, rgb, sizeof rgb);
			}
		}
		double share = 100.0 * within / (W * H);
		int ok = share >= 99.5;
		printf("%s: %s: %.2f%% of pixels within 3/255, largest difference %.4f at (%d, %d): "
		       "%.4f %.4f %.4f, POV-Ray %.4f %.4f %.4f\n",
		       ok ? "ok" : "FAIL", c->name, share, max_diff, worst % W, worst / W, worst_rgb[0], worst_rgb[1],
		       worst_rgb[2], pov[3 * worst], pov[3 * worst + 1], pov[3 * worst + 2]);
		failures += !ok;
	}
	plane_close(&pd);
	return failures != 0;
}

int main(int argc, char **argv)
{
	return plane_main(argc, argv, "test_normal", N_CASES, write_scene, compare);
}
