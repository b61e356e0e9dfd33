/* eval_sweep.c: what a sphere_sweep { } says before its object modifiers, as
 * POV-Ray 3.7's Parse_Sphere_Sweep reads it: its spline (linear_spline,
 * cubic_spline or b_spline, which it must have), the number of spheres (at
 * least 2, or 4 for the cubic splines), each sphere's centre and radius, and
 * an optional tolerance (1e-6). The spheres go to scene.outlines as
 * (x, y, z, radius) (src/shape_sphere_sweep.c). A radius below 0, which
 * POV-Ray takes and squares, is an error here. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"
#include "sweep.h"

#define SWEEP_MAX_SPHERES 1000000

/* The next item as a float or vector (out[] 1 or 3 of them). */
static int next_value(struct eval *e, struct cursor *c, const ast_node *b, int i, int n, bool vector, double *out)
{
	int err = 0;
	const ast_node *arg = eval_next_expr(c, &err);
	if (!arg) {
		if (!err) {
			const ast_node *next = eval_next(c, &err);
			eval_error(e, next ? next->loc : b->loc, "sphere_sweep has %d spheres of the %d its count says", i, n);
		}
		return -1;
	}
	if (vector ? eval_expect_vector(e, arg, out) : eval_expect_float(e, arg, out))
		return -1;
	for (int k = 0; k < (vector ? 3 : 1); k++)
		if (!isfinite(out[k])) {
			eval_error(e, arg->loc, "sphere_sweep's sphere %d is not a number", i + 1);
			return -1;
		}
	if (!vector && out[0] < 0) {
		eval_error(e, arg->loc, "sphere_sweep's sphere %d has a radius below 0 (%g)", i + 1, out[0]);
		return -1;
	}
	return 0;
}

int eval_sweep_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	static const char *const splines[] = {
		[SWEEP_LINEAR] = AST_WORD_LINEAR_SPLINE, [SWEEP_CUBIC] = AST_WORD_CUBIC_SPLINE,
		[SWEEP_B_SPLINE] = AST_WORD_B_SPLINE,
	};
	int err = 0, kind = -1;
	const ast_node *item = eval_next(c, &err);
	if (err)
		return -1;
	if (item && item->kind == AST_IDENT && !eval_lookup(e, item->str))
		for (int i = 0; i < 3; i++)
			if (strcmp(item->str, splines[i]) == 0)
				kind = i;
	if (kind < 0) {
		eval_error(e, item ? item->loc : b->loc, "sphere_sweep needs its spline first: linear_spline, "
		           "cubic_spline or b_spline");
		return -1;
	}
	double f;
	const ast_node *arg = eval_next_expr(c, &err);
	if (!arg) {
		if (!err)
			eval_error(e, item->loc, "sphere_sweep needs the number of its spheres after its spline");
		return -1;
	}
	if (eval_expect_float(e, arg, &f))
		return -1;
	int least = kind == SWEEP_LINEAR ? 2 : 4;
	if (!(f >= least)) {
		eval_error(e, arg->loc, "too few spheres for a sphere_sweep's %s: %g (it needs at least %d)", splines[kind],
		           f, least);
		return -1;
	}
	if (!(f <= SWEEP_MAX_SPHERES)) {
		eval_error(e, arg->loc, "a sphere_sweep of %g spheres: at most %d", f, SWEEP_MAX_SPHERES);
		return -1;
	}
	int n = (int)f;
	scene_outline ol = { .edge = eval_xrealloc(NULL, (size_t)n * sizeof *ol.edge), .n_edges = n };
	for (int i = 0; i < n; i++)
		if (next_value(e, c, b, i, n, true, ol.edge[i]) || next_value(e, c, b, i, n, false, &ol.edge[i][3])) {
			free(ol.edge);
			return -1;
		}
	o->param[0] = kind;
	o->param[1] = 1e-6;   /* POV-Ray's DEPTH_TOLERANCE */
	item = eval_next(c, &err);
	const ast_node *neg;
	const char *w = item ? eval_word_item(item, &neg) : NULL;
	if (w && strcmp(w, AST_WORD_TOLERANCE) == 0) {
		if (eval_word_float(e, c, item, neg, &o->param[1])) {
			free(ol.edge);
			return -1;
		}
	} else if (item) {
		eval_unget(c, item);   /* the object modifiers */
	}
	if (err) {
		free(ol.edge);
		return -1;
	}
	o->outline = scene_add_outline(e->s, &ol);
	return 0;
}
