/* test_sweep.c: the sphere_sweep on the device (through eclat's lowering
 * and kernels/raycast.cl's shapecast) against its host class
 * (src/shape_sphere_sweep.c: trace() and the inside test, in double), and
 * the host's trace() against brute force, as tests/shape_check.h says.
 *
 *   test_sweep [RAYS]
 *
 * Each case is one sweep (linear, cubic_spline, b_spline; thin and fat, a
 * radius growing faster than its centre moves, a sphere inside the next, a
 * curve that doubles back through itself), transformed, one far from the
 * origin; its own rays go at the joints between its segments (toward points
 * near a modelling sphere's surface where two segments meet). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shape_check.h"
#include "sweep.h"

static int failures;

/* The modelling spheres at the ends of the segments, in world space. */
struct joints {
	double (*at)[4];
	int n;
};

/* Near a joint sphere's surface. */
static void aim_joint(const check_case *c, int i, const double org[3], double d[3], void *arg)
{
	const struct joints *js = arg;
	(void)c;
	/* the point of the box that the other kinds aim at, drawn and unused so
	 * that the rays stay the ones these cases were first run with */
	for (int k = 0; k < 3; k++)
		(void)cast_uniform();
	const double *j = js->at[i % js->n];
	double v[3], s = j[3] * (1 + 0.02 * (2 * cast_uniform() - 1));
	cast_random_unit(v);
	for (int k = 0; k < 3; k++)
		d[k] = j[k] + s * v[k] - org[k];
}

/* ---- cases ---- */

struct shape_case {
	const char *name;
	int kind, n;
	const double (*sp)[4];
	double rot[3], sc[3], mv[3];
};

static scene_object make(scene *sc, const struct shape_case *c)
{
	scene_object o = { .shape = SHAPE_SPHERE_SWEEP, .xf = scene_xform_identity(),
	                   .material = scene_default_material(), .mesh = -1, .loc = SRC_NOWHERE };
	scene_outline ol = { .edge = malloc((size_t)c->n * sizeof *ol.edge), .n_edges = c->n };
	memcpy(ol.edge, c->sp, (size_t)c->n * sizeof *ol.edge);
	o.outline = scene_add_outline(sc, &ol);
	o.param[0] = c->kind;
	o.param[1] = 1e-6;
	xform r = scene_xform_rotate(c->rot), s = scene_xform_scale(c->sc), t = scene_xform_translate(c->mv);
	o.xf = scene_xform_then(&s, &r);
	o.xf = scene_xform_then(&o.xf, &t);
	return o;
}

static void test_case(device_ctx *dev, cl_program prog, const struct shape_case *c, int n_rays)
{
	scene sc;
	scene_init(&sc);
	scene_object made = make(&sc, c);
	scene_add_object(&sc, &made);
	lower_result lr;
	lower_options opt = { LOWER_BVH_SAH, 24, LOWER_LAYOUT_DEFAULT, 0, 0, 0, NULL };
	if (lower_scene(&sc, &opt, &lr) || lr.n_prims < 1) {
		printf("FAIL: %s: lowering made %d primitives\n", c->name, lr.n_prims);
		failures++;
		scene_free(&sc);
		return;
	}
	const scene_object *o = &sc.objects[0];
	check_case cc;
	check_case_init(&cc, &sc, o);
	/* the joints: the ends of the segments (the spheres at u = 0 and 1) */
	int nseg = sweep_segments(&sc, o);
	struct joints js = { malloc((size_t)(nseg + 1) * sizeof *js.at), nseg + 1 };
	for (int j = 0; j < js.n; j++) {
		sweep_seg g;
		sweep_segment(&sc, o, j < nseg ? j : nseg - 1, &g);
		double p[4];
		for (int q = 0; q < 4; q++)
			p[q] = j < nseg ? g.c[0][q] : g.c[0][q] + g.c[1][q] + g.c[2][q] + g.c[3][q];
		scene_xform_point(&o->xf, p, js.at[j]);
		double ax[3] = { p[3], 0, 0 }, w[3];   /* the radius, roughly, in world space */
		scene_xform_vector(&o->xf, ax, w);
		js.at[j][3] = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
	}
	check_kind joint = { "at its joints", aim_joint, &js };
	failures += check_shape(dev, prog, &lr, &cc, c->name, &joint, false, n_rays);
	free(js.at);
	lower_free(&lr);
	scene_free(&sc);
}

int main(int argc, char **argv)
{
	int n_rays = argc > 1 ? atoi(argv[1]) : 2000;
	if (n_rays <= 0) {
		fprintf(stderr, "usage: test_sweep [RAYS]\n");
		return 2;
	}
	device_ctx dev;
	cl_program prog = check_start(&dev);
	if (!prog)
		return 1;
	static const double zigzag[][4] = {
		{ -2, 0, 0, 0.3 }, { -0.5, 1, 0.5, 0.6 }, { 0.8, 0, -0.3, 0.2 }, { 2, 0.8, 0.4, 0.5 },
	};
	static const double wave[][4] = {
		{ -3, -0.5, 0, 0.3 }, { -2, 0, 0, 0.3 }, { -0.5, 1, 0.5, 0.6 }, { 0.8, 0, -0.3, 0.2 },
		{ 2, 0.8, 0.4, 0.5 }, { 3, 0, 0, 0.2 },
	};
	static const double thin[][4] = {
		{ 0, 0, 0, 0.02 }, { 1, 0, 0, 0.05 }, { 1, 1, 0, 0.01 }, { 0, 1, 1, 0.04 }, { 0, 0, 1, 0.03 },
	};
	/* a sphere that swallows the next, and a radius growing faster than the centre moves */
	static const double swallow[][4] = { { 0, 0, 0, 1 }, { 0.3, 0, 0, 0.2 }, { 1.5, 0.2, 0, 0.9 }, { 1.6, 0, 0, 0.1 } };
	/* a loop through itself, fat (the envelope folds) */
	static const double loop[][4] = {
		{ -1, -1, 0, 0.3 }, { 0, 0, 0, 0.5 }, { 1, 1, 0.2, 0.4 }, { 1, -0.5, 0.1, 0.6 }, { 0, 0.8, -0.1, 0.5 },
		{ -1, 1, 0, 0.3 }, { -1.2, -1, 0.3, 0.4 },
	};
	/* a helix of many segments, which lowering splits among several primitives */
	static double helix[40][4];
	for (int i = 0; i < 40; i++) {
		helix[i][0] = cos(i * 0.5), helix[i][1] = -1 + i * 0.05, helix[i][2] = sin(i * 0.5);
		helix[i][3] = 0.12 + 0.05 * sin(i * 0.7);
	}
	const double none[3] = { 0, 0, 0 }, one[3] = { 1, 1, 1 }, tilt[3] = { 30, 40, 50 };
	const double uneven[3] = { 1.5, 0.6, 1 }, far[3] = { 3000.3, -1700.7, 2900.1 }, big[3] = { 40, 40, 40 };
	const double near[3] = { 0.3, -0.2, 0.5 };
#define CASE(name, kind, sp, rot, sc, mv) \
	{ name, kind, (int)(sizeof sp / sizeof sp[0]), sp, { rot[0], rot[1], rot[2] }, { sc[0], sc[1], sc[2] }, \
	  { mv[0], mv[1], mv[2] } }
	struct shape_case cases[] = {
		CASE("linear zigzag", SWEEP_LINEAR, zigzag, none, one, none),
		CASE("linear zigzag, turned, scaled unevenly", SWEEP_LINEAR, zigzag, tilt, uneven, near),
		CASE("linear, a sphere inside the next", SWEEP_LINEAR, swallow, tilt, one, near),
		CASE("linear thin", SWEEP_LINEAR, thin, tilt, one, none),
		CASE("cubic_spline wave", SWEEP_CUBIC, wave, none, one, none),
		CASE("cubic_spline wave, turned, scaled unevenly", SWEEP_CUBIC, wave, tilt, uneven, near),
		CASE("cubic_spline thin", SWEEP_CUBIC, thin, tilt, one, near),
		CASE("cubic_spline fat loop", SWEEP_CUBIC, loop, tilt, one, none),
		CASE("cubic_spline, radius outgrowing the centre", SWEEP_CUBIC, swallow, none, one, near),
		CASE("b_spline wave", SWEEP_B_SPLINE, wave, tilt, one, none),
		CASE("b_spline fat loop, scaled unevenly", SWEEP_B_SPLINE, loop, tilt, uneven, near),
		CASE("b_spline thin", SWEEP_B_SPLINE, thin, none, one, none),
		CASE("b_spline wave, scaled 40 and 4000 units away", SWEEP_B_SPLINE, wave, tilt, big, far),
		CASE("linear helix of 39 segments", SWEEP_LINEAR, helix, tilt, one, near),
		CASE("cubic_spline helix of 37 segments, scaled unevenly", SWEEP_CUBIC, helix, tilt, uneven, none),
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
		test_case(&dev, prog, &cases[i], n_rays);
	clReleaseProgram(prog);
	device_close(&dev);
	printf("%s\n", failures ? "FAIL" : "all sphere_sweep checks passed");
	return failures ? 1 : 0;
}
