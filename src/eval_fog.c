/* eval_fog.c: POV-Ray's fog { }, read as POV-Ray 3.7's Parse_Fog reads it
 * (its defaults are scene_default_fog's). Every fog statement adds one fog to
 * the scene; the kernels combine them (kernels/fog.cl). */
#include <math.h>
#include <string.h>

#include "eval_int.h"

/* POV-Ray's negative distance makes light out of nothing. */
static int fog_distance(struct eval *e, const ast_node *at, double d, scene_fog *f)
{
	if (d < 0) {
		eval_error(e, at->loc, "a fog's distance must be positive, not %g", d);
		return -1;
	}
	f->distance = d;
	return 0;
}

/* An expression among a fog's items: a declared fog (first only), a colour,
 * or a bare float, which POV-Ray takes for the distance with a warning. */
static int fog_expression(struct eval *e, const ast_node *item, scene_fog *f, bool first)
{
	value v;
	if (eval_expr(e, item, &v))
		return -1;
	int rc = 0;
	if (v.kind == V_FOG && first) {
		src_loc loc = f->loc;
		*f = *v.fog;
		f->loc = loc;
	} else if (v.kind == V_FLOAT) {
		eval_warn_once(e, item->loc, "fog distance", "a fog's distance should follow the keyword distance");
		rc = fog_distance(e, item, v.v[0], f);
	} else if (v.kind == V_FOG) {
		eval_error(e, item->loc, "a declared fog must come first in fog { }");
		rc = -1;
	} else {
		double col[5];
		rc = eval_expect_color(e, item, col);
		for (int i = 0; i < 5 && rc == 0; i++)
			f->colour[i] = (float)col[i];
	}
	eval_value_free(&v);
	return rc;
}

/* The turbulence's items: any of them makes the fog turbulent, as in POV-Ray,
 * where an octaves alone creates a turbulence of <0, 0, 0>. */
static int fog_turbulence(struct eval *e, const ast_node *item, scene_fog *f)
{
	double x;
	f->has_turb = true;
	switch (item->kw) {
	case KW_TURBULENCE:
		return eval_expect_vector(e, item->kids[0], f->turbulence);
	case KW_OCTAVES:
		if (eval_expect_float(e, item->kids[0], &x))
			return -1;
		f->octaves = x < 1 ? 1 : x > 10 ? 10 : eval_int_of(x);
		return 0;
	case KW_OMEGA:
		return eval_expect_float(e, item->kids[0], &f->omega);
	default:
		return eval_expect_float(e, item->kids[0], &f->lambda);
	}
}

static int fog_arg(struct eval *e, const ast_node *item, scene_fog *f)
{
	double x;
	switch (item->kw) {
	case KW_DISTANCE:
		return eval_expect_float(e, item->kids[0], &x) ? -1 : fog_distance(e, item->kids[0], x, f);
	case KW_FOG_OFFSET: return eval_expect_float(e, item->kids[0], &f->offset);
	case KW_FOG_ALT: return eval_expect_float(e, item->kids[0], &f->alt);
	case KW_TURB_DEPTH: return eval_expect_float(e, item->kids[0], &f->turb_depth);
	case KW_UP: return eval_expect_vector(e, item->kids[0], f->up);
	case KW_TURBULENCE: case KW_OCTAVES: case KW_OMEGA: case KW_LAMBDA:
		return fog_turbulence(e, item, f);
	case KW_FOG_TYPE:
		if (eval_expect_float(e, item->kids[0], &x))
			return -1;
		f->type = eval_int_of(x);
		if (f->type != SCENE_FOG_CONSTANT && f->type != SCENE_FOG_GROUND)   /* POV-Ray's constant fog */
			eval_warning(e, item->kids[0]->loc, "unknown fog_type %g (1: constant, 2: ground); "
			             "a constant fog is made, as POV-Ray does", x);
		return 0;
	default:
		return 1;
	}
}

static int fog_item(struct eval *e, struct cursor *c, const ast_node *item, scene_fog *f, bool first)
{
	xform t = scene_xform_identity();
	int rc = eval_transform_item(e, c, item, &t);
	if (rc > 0 && item->kw == KW_TRANSLATE)
		eval_warning(e, item->loc, "a fog's up vector cannot be translated; translate ignored");
	else if (rc > 0)   /* POV-Ray turns the up vector only */
		scene_xform_vector(&t, f->up, f->up);
	if (rc != 0)
		return rc < 0 ? -1 : 0;
	if (AST_IS_EXPRESSION(item->kind))
		return fog_expression(e, item, f, first);
	if (item->kind == AST_ARG && (rc = fog_arg(e, item, f)) <= 0)
		return rc;
	return eval_not_valid(e, item, "a fog");
}

/* What POV-Ray would draw wrong or not at all, refused or said. */
static int fog_check(struct eval *e, const ast_node *b, scene_fog *f)
{
	if (f->type == SCENE_FOG_GROUND && f->alt == 0) {
		eval_error(e, b->loc, "a ground fog (fog_type 2) needs a fog_alt other than 0");
		return -1;
	}
	double len = sqrt(f->up[0] * f->up[0] + f->up[1] * f->up[1] + f->up[2] * f->up[2]);
	if (f->type == SCENE_FOG_GROUND && !(len > 0)) {
		eval_error(e, b->loc, "a ground fog's up vector must not be <0, 0, 0>");
		return -1;
	}
	for (int k = 0; k < 3 && len > 0; k++)
		f->up[k] /= len;
	return 0;
}

/* fog { [FOG_IDENTIFIER] [fog_type 1 | 2] [distance F] [COLOR] [fog_offset F]
 *       [fog_alt F] [turbulence <T>] [octaves N] [omega F] [lambda F]
 *       [turb_depth F] [up <U>] [TRANSFORMATIONS...] } */
int eval_fog(struct eval *e, const ast_node *b, scene_fog *out)
{
	scene_fog f = scene_default_fog();
	f.loc = b->loc;
	struct cursor c;
	int err = 0, rc = 0;
	bool first = true;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		rc = fog_item(e, &c, item, &f, first);
		first = false;
	}
	eval_cursor_free(&c);
	if (rc || err || fog_check(e, b, &f))
		return -1;
	*out = f;
	return 0;
}

/* A fog statement: POV-Ray skips a fog of distance 0 (the default). */
int eval_fog_statement(struct eval *e, const ast_node *b)
{
	scene_fog f;
	if (eval_fog(e, b, &f))
		return -1;
	if (f.distance == 0)
		eval_warning(e, b->loc, "a fog without a distance (or of distance 0) has no effect");
	else
		scene_add_fog(e->s, &f);
	return 0;
}

/* #declare F = fog { ... } */
int eval_fog_value(struct eval *e, const ast_node *b, value *out)
{
	scene_fog f;
	if (eval_fog(e, b, &f))
		return -1;
	*out = (value){ .kind = V_FOG, .fog = eval_xrealloc(NULL, sizeof f) };
	*out->fog = f;
	return 0;
}
