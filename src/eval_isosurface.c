/* eval_isosurface.c: what an isosurface { } says before its object modifiers,
 * in POV-Ray 3.7's order and with its defaults (Parse_Isosurface): its function
 * first, then contained_by, threshold, accuracy, max_gradient, max_trace,
 * all_intersections, open, polarity and evaluate in any order. The numbers go
 * where src/shape_isosurface.c reads them. */
#include <string.h>

#include "eval_int.h"

#define MAX_TRACE 10   /* POV-Ray's ISOSURFACE_MAXTRACE */

static const char *word(const ast_node *n)
{
	return n->kind == AST_IDENT ? n->str : NULL;
}

const char *eval_word_item(const ast_node *n, const ast_node **negated)
{
	*negated = NULL;
	if (n->kind == AST_BINARY && n->op == '-' && n->kids[0]->kind == AST_IDENT) {
		*negated = n->kids[1];
		return n->kids[0]->str;
	}
	return word(n);
}

int eval_word_float(struct eval *e, struct cursor *c, const ast_node *at, const ast_node *negated, double *f)
{
	if (negated) {
		int rc = eval_expect_float(e, negated, f);
		*f = -*f;
		return rc;
	}
	int err = 0;
	const ast_node *arg = eval_next_expr(c, &err);
	if (!arg) {
		if (!err)
			eval_error(e, at->loc, "'%s' needs a float after it", word(at));
		return -1;
	}
	return eval_expect_float(e, arg, f);
}

/* contained_by { box { <Corner1>, <Corner2> } | sphere { <Centre>, Radius } } */
int eval_contained_by(struct eval *e, const ast_node *b, scene_object *o)
{
	struct cursor c;
	int err = 0, rc = -1;
	eval_cursor_init(&c, e, b);
	const ast_node *shape = eval_next(&c, &err);
	const ast_node *more = shape ? eval_next(&c, &err) : NULL;
	if (shape && !more && shape->kind == AST_BLOCK && (shape->kw == KW_BOX || shape->kw == KW_SPHERE)) {
		struct cursor a;
		eval_cursor_init(&a, e, shape);
		const ast_node *p = eval_next_expr(&a, &err), *q = p ? eval_next_expr(&a, &err) : NULL;
		const ast_node *extra = q ? eval_next(&a, &err) : NULL;
		bool sphere = shape->kw == KW_SPHERE;
		if (!p || !q || extra) {
			if (!err)
				eval_error(e, (extra ? extra : shape)->loc, "contained_by's %s takes %s and nothing else",
				           sphere ? "sphere" : "box", sphere ? "a centre and a radius" : "two corners");
		} else if (eval_expect_vector(e, p, o->p[0]) == 0 &&
		           (sphere ? eval_expect_float(e, q, &o->radius) : eval_expect_vector(e, q, o->p[1])) == 0) {
			rc = 0;
			o->n[0][0] = sphere;
			for (int k = 0; !sphere && k < 3; k++)   /* POV-Ray orders the corners */
				if (o->p[0][k] > o->p[1][k]) {
					double t = o->p[0][k];
					o->p[0][k] = o->p[1][k];
					o->p[1][k] = t;
				}
		}
		eval_cursor_free(&a);
	} else if (!err) {
		eval_error(e, (more ? more : shape ? shape : b)->loc, "contained_by holds one box { } or sphere { }");
	}
	eval_cursor_free(&c);
	return rc;
}

int eval_isosurface_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	int err = 0;
	const ast_node *item = eval_next(c, &err);
	if (!item || item->kind != AST_FUNCTION) {
		if (!err)
			eval_error(e, item ? item->loc : b->loc, "an isosurface starts with its function { }");
		return -1;
	}
	/* the device runs it, with the scene's patterns; trace() and inside() refuse
	 * one that calls them (eval_trace.c) */
	int rc = eval_function_pattern_index(e, item, "the isosurface is left out", &o->function);
	if (rc < 0)
		return -1;
	if (rc > 0)
		o->function = -1;   /* --skip-unsupported: left out, with the warning */
	double box[2][3] = { { -1, -1, -1 }, { 1, 1, 1 } };
	memcpy(o->p, box, sizeof box);
	o->param[0] = 0;      /* threshold */
	o->param[1] = 0.001;  /* accuracy */
	o->param[2] = 1.1;    /* max_gradient */
	o->param[3] = 1;      /* max_trace */
	while ((item = eval_next(c, &err)) != NULL) {
		const ast_node *neg;
		const char *w = eval_word_item(item, &neg);
		if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && strcmp(item->str, AST_WORD_CONTAINED_BY) == 0) {
			rc = eval_contained_by(e, item, o);
		} else if (w && strcmp(w, AST_WORD_THRESHOLD) == 0) {
			rc = eval_word_float(e, c, item, neg, &o->param[0]);
		} else if (w && strcmp(w, AST_WORD_ACCURACY) == 0) {
			rc = eval_word_float(e, c, item, neg, &o->param[1]);
		} else if (w && strcmp(w, AST_WORD_MAX_GRADIENT) == 0) {
			rc = eval_word_float(e, c, item, neg, &o->param[2]);
		} else if (w && strcmp(w, AST_WORD_MAX_TRACE) == 0) {
			double n;
			rc = eval_word_float(e, c, item, neg, &n);
			if (rc == 0 && !(n >= 1 && n < MAX_TRACE + 1)) {
				eval_error(e, item->loc, "isosurface max_trace is 1 to %d, not %g", MAX_TRACE, n);
				rc = -1;
			}
			o->param[3] = (int)n;
		} else if (w && strcmp(w, AST_WORD_ALL_INTERSECTIONS) == 0) {
			o->param[3] = MAX_TRACE;
		} else if (w && strcmp(w, AST_WORD_OPEN) == 0) {
			o->shape_flags |= SHAPE_OPEN;
		} else if (w && strcmp(w, AST_WORD_POLARITY) == 0) {
			double p;
			rc = eval_word_float(e, c, item, neg, &p);
			o->n[0][1] = p > 0;
		} else if (w && strcmp(w, AST_WORD_EVALUATE) == 0) {
			double v[3];
			for (int i = 0; i < 3 && rc == 0; i++)
				rc = eval_word_float(e, c, item, i == 0 ? neg : NULL, &v[i]);
			if (rc == 0)
				eval_warn_once(e, item->loc, "isosurface evaluate", "isosurface 'evaluate' is not supported yet; "
				               "max_gradient is used as written");
		} else {
			eval_unget(c, item);   /* the object modifiers */
			break;
		}
		if (rc)
			return -1;
	}
	if (err)
		return -1;
	if (!(o->param[1] > 0)) {
		eval_warning(e, b->loc, "isosurface 'accuracy' is not positive; using 0.001 (POV-Ray's default)");
		o->param[1] = 0.001;
	}
	if (!(o->param[2] > 0)) {
		eval_warning(e, b->loc, "isosurface 'max_gradient' is not positive; using 1.1 (POV-Ray's default)");
		o->param[2] = 1.1;
	}
	if (o->n[0][0] != 0 && !(o->radius > 0)) {
		eval_error(e, b->loc, "an isosurface's contained_by sphere needs a radius above 0");
		return -1;
	}
	return 0;
}
