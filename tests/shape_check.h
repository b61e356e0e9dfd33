/* shape_check.h: what test_torus and test_sweep share: one shape alone in a
 * scene, cast on the device through kernels/raycast.cl's shapecast and held
 * to its host class (trace() and the inside test, in double), and the host's
 * trace() held to brute force.
 *
 * Its rays come from around the shape toward its box, from inside its box in
 * any direction, along its surface (grazing it, just inside or outside), and
 * of a kind of the shape's own (check_kind). A ray's closest hit must agree
 * with the host's (hit or miss, the distance to 1e-4, the normal to 0.999),
 * any-hit with closest-hit, and the inside test at its origin with the
 * host's; a disagreement passes only where the host itself answers otherwise
 * for a ray within rounding of it (2 float epsilons of its coordinates away,
 * 16 on a device without double). The host's nearest hit is held to the
 * inside test sampled densely along the ray: no hit may come after a crossing
 * it sees, and a hit it does not see must be a grazing one (or, when the
 * caller says so, a spindle torus's inner surface, whose sides are both
 * inside). */
#ifndef ECLAT_TESTS_SHAPE_CHECK_H
#define ECLAT_TESTS_SHAPE_CHECK_H

#include <stdbool.h>

#include "cast.h"

/* The shape, the inverse of its transform, and its box in world space. */
typedef struct {
	cast_shape sh;
	double lo[3], hi[3], c[3], r;   /* c: the box's centre; r: half its diagonal */
} check_case;

/* The shape of object o of scene s. */
void check_case_init(check_case *c, const scene *s, const scene_object *o);

/* The shape's own kind of ray: aim gives ray i, from org (around the box),
 * its direction d (any length), where the other kinds draw a point of the box
 * to aim at. */
typedef struct {
	const char *name;   /* "through its centre" */
	void (*aim)(const check_case *c, int i, const double org[3], double d[3], void *arg);
	void *arg;
} check_kind;

/* Opens the first device and builds the kernels for shapecast, printing the
 * device and whether it solves in double (which sets the rounding allowed).
 * NULL after printing why not. */
cl_program check_start(device_ctx *dev);

/* Casts n_rays rays of each kind (half as many grazing and of the shape's
 * own) at the shape, lowered alone into lr, and prints an ok/FAIL line for the
 * device against the host and one for the host against brute force (on up to
 * 400 rays) per kind, naming them "NAME, KIND". Returns the number of FAIL
 * lines. */
int check_shape(device_ctx *dev, cl_program prog, const lower_result *lr, const check_case *c, const char *name,
                const check_kind *own, bool spindle, int n_rays);

#endif
