/* test_torus.c: the torus and the superellipsoid on the device (through
 * eclat's lowering and kernels/raycast.cl's shapecast) against their host
 * classes (src/shape_torus.c, src/shape_superellipsoid.c: trace() and the
 * inside test, in double), and the host's trace() against brute force, as
 * tests/shape_check.h says.
 *
 *   test_torus [RAYS]
 *
 * Each case is one shape, thin and fat, transformed, far from the origin; its
 * own rays go through its centre (a torus's hole, a spindle torus's tips).
 * Only grazing rays and origins on the surface disagree within rounding, and
 * a spindle torus's inner surface is a hit that brute force does not see. */
#include <stdio.h>
#include <stdlib.h>

#include "shape_check.h"

static int failures;

/* Through its centre: a torus's hole, a spindle torus's tips. */
static void aim_centre(const check_case *c, int i, const double org[3], double d[3], void *arg)
{
	(void)i, (void)arg;
	double centre[3], zero[3] = { 0, 0, 0 };
	scene_xform_point(&c->sh.o->xf, zero, centre);
	for (int k = 0; k < 3; k++)
		d[k] = centre[k] + 0.05 * c->r * (2 * cast_uniform() - 1) - org[k];
}

/* ---- cases ---- */

struct shape_case {
	const char *name;
	scene_object o;
};

static scene_object make(scene_shape shape, double a, double b, const double rot[3], const double sc[3],
                         const double mv[3])
{
	scene_object o = { .shape = shape, .xf = scene_xform_identity(), .material = scene_default_material(),
	                   .mesh = -1, .loc = SRC_NOWHERE };
	if (shape == SHAPE_TORUS) {
		o.radius = a;
		o.param[0] = b;
	} else {
		o.p[0][0] = a;
		o.p[0][1] = b;
	}
	xform r = scene_xform_rotate(rot), s = scene_xform_scale(sc), t = scene_xform_translate(mv);
	o.xf = scene_xform_then(&s, &r);
	o.xf = scene_xform_then(&o.xf, &t);
	return o;
}

static void test_case(device_ctx *dev, cl_program prog, const struct shape_case *c, int n_rays)
{
	scene sc;
	scene_init(&sc);
	scene_add_object(&sc, &c->o);
	lower_result lr;
	lower_options opt = { LOWER_BVH_SAH, 24, LOWER_LAYOUT_DEFAULT, 0, 0, 0, NULL };
	if (lower_scene(&sc, &opt, &lr) || lr.n_prims != 1) {
		printf("FAIL: %s: lowering made %d primitives\n", c->name, lr.n_prims);
		failures++;
		scene_free(&sc);
		return;
	}
	const scene_object *o = &sc.objects[0];
	check_case cc;
	check_case_init(&cc, &sc, o);
	bool spindle = o->shape == SHAPE_TORUS && o->param[0] > o->radius;
	check_kind centre = { "through its centre", aim_centre, NULL };
	failures += check_shape(dev, prog, &lr, &cc, c->name, &centre, spindle, n_rays);
	lower_free(&lr);
	scene_free(&sc);
}

int main(int argc, char **argv)
{
	int n_rays = argc > 1 ? atoi(argv[1]) : 4000;
	if (n_rays <= 0) {
		fprintf(stderr, "usage: test_torus [RAYS]\n");
		return 2;
	}
	device_ctx dev;
	cl_program prog = check_start(&dev);
	if (!prog)
		return 1;
	const double none[3] = { 0, 0, 0 }, one[3] = { 1, 1, 1 };
	const double tilt[3] = { 30, 40, 50 }, uneven[3] = { 1.5, 0.6, 1 }, far[3] = { 3000.3, -1700.7, 2900.1 };
	const double big[3] = { 40, 40, 40 }, near[3] = { 0.3, -0.2, 0.5 };
	struct shape_case cases[] = {
		{ "torus 1, 0.25", make(SHAPE_TORUS, 1, 0.25, none, one, none) },
		{ "thin torus 2, 0.02, turned", make(SHAPE_TORUS, 2, 0.02, tilt, one, near) },
		{ "torus 1, 0.4 scaled unevenly", make(SHAPE_TORUS, 1, 0.4, tilt, uneven, near) },
		{ "horn torus 0.5, 0.5", make(SHAPE_TORUS, 0.5, 0.5, tilt, one, none) },
		{ "spindle torus 0.6, 1", make(SHAPE_TORUS, 0.6, 1, tilt, one, near) },
		{ "torus 1, 0.3, scaled 40 and 4000 units away", make(SHAPE_TORUS, 1, 0.3, tilt, big, far) },
		{ "superellipsoid <1, 1> (a sphere)", make(SHAPE_SUPERELLIPSOID, 1, 1, none, one, none) },
		{ "superellipsoid <0.2, 0.3>, turned", make(SHAPE_SUPERELLIPSOID, 0.2, 0.3, tilt, one, near) },
		{ "superellipsoid <2.5, 0.5> scaled unevenly", make(SHAPE_SUPERELLIPSOID, 2.5, 0.5, tilt, uneven, near) },
		{ "superellipsoid <3, 3> (pinched)", make(SHAPE_SUPERELLIPSOID, 3, 3, tilt, one, none) },
		{ "superellipsoid <0.5, 2>, scaled 40 and 4000 units away",
		  make(SHAPE_SUPERELLIPSOID, 0.5, 2, tilt, big, far) },
		{ "superellipsoid <0, 0.7> (square sections)", make(SHAPE_SUPERELLIPSOID, 0, 0.7, tilt, one, near) },
		{ "superellipsoid <0.3, 0.7>", make(SHAPE_SUPERELLIPSOID, 0.3, 0.7, tilt, uneven, none) },
		{ "superellipsoid <2.5, 4> (pinched)", make(SHAPE_SUPERELLIPSOID, 2.5, 4, tilt, one, near) },
		{ "superellipsoid <0.5, 3>", make(SHAPE_SUPERELLIPSOID, 0.5, 3, tilt, one, none) },
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
		test_case(&dev, prog, &cases[i], n_rays);
	clReleaseProgram(prog);
	device_close(&dev);
	printf("%s\n", failures ? "FAIL" : "all torus and superellipsoid checks passed");
	return failures ? 1 : 0;
}
