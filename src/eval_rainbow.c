/* eval_rainbow.c: POV-Ray's rainbow { }, read as POV-Ray 3.7's Parse_Rainbow
 * reads it (its defaults are Create_Rainbow's), into the form ComputeRainbow
 * uses (scene.h, scene_rainbow). Every rainbow statement adds one rainbow to
 * the scene; the kernels blend them (kernels/rainbow.cl). */
#include <math.h>
#include <string.h>

#include "eval_int.h"
#include "vec3.h"

#define RAINBOW_EPSILON 1e-10   /* POV-Ray's EPSILON, for its vector tests */

/* Create_Rainbow's: arc and falloff of 180 (radians: every ray is inside the
 * arc), no direction (an error unless one is given), up y, right x. */
static scene_rainbow rainbow_default(src_loc loc)
{
	return (scene_rainbow){ .up = { 0, 1, 0 }, .right = { 1, 0, 0 }, .distance = 1e7, .arc_angle = 180,
	                        .falloff_angle = 180, .pigment = -1, .loc = loc };
}

/* The colour_map as POV-Ray makes it the rainbow's pigment: a gradient x,
 * read at the colour's index along x. */
static int rainbow_map(struct eval *e, const ast_node *item, scene_rainbow *r)
{
	value v;
	if (eval_material_value(e, item, &v))
		return -1;
	int from = v.mat.pattern;
	eval_value_free(&v);
	if (from < 0 || from >= e->s->n_pigments) {   /* an empty map */
		r->pigment = -1;
		return 0;
	}
	scene_pigment pg;
	eval_pattern_defaults(&pg, PATTERN_GRADIENT, item->loc);
	const scene_pigment *map = &e->s->pigments[from];
	pg.n_map = map->n_map;
	pg.map = eval_xrealloc(NULL, (map->n_map ? map->n_map : 1) * sizeof *pg.map);
	memcpy(pg.map, map->map, map->n_map * sizeof *pg.map);
	pg.map_written = true;
	r->pigment = scene_add_pigment(e->s, &pg);
	return 0;
}

/* arc_angle and falloff_angle: 0 to 360 degrees, kept halved in radians. */
static int rainbow_angle(struct eval *e, const ast_node *item, double *out, bool *set)
{
	double x;
	if (eval_expect_float(e, item->kids[0], &x))
		return -1;
	if (!(x >= 0 && x <= 360)) {
		eval_error(e, item->kids[0]->loc, "a rainbow's %s must be from 0 to 360 degrees, not %g",
		           ast_keyword_name(item->kw), x);
		return -1;
	}
	*out = x * M_PI / 360;
	*set = true;
	return 0;
}

/* The items; arc and falloff say whether those angles were written. */
struct rainbow_read {
	scene_rainbow r;
	bool arc, falloff;
};

static int rainbow_arg(struct eval *e, const ast_node *item, struct rainbow_read *rd)
{
	scene_rainbow *r = &rd->r;
	switch (item->kw) {
	case KW_ANGLE: return eval_expect_float(e, item->kids[0], &r->angle);
	case KW_WIDTH: return eval_expect_float(e, item->kids[0], &r->width);
	case KW_DISTANCE: return eval_expect_float(e, item->kids[0], &r->distance);
	case KW_DIRECTION: return eval_expect_vector(e, item->kids[0], r->direction);
	case KW_UP: return eval_expect_vector(e, item->kids[0], r->up);
	case KW_ARC_ANGLE: return rainbow_angle(e, item, &r->arc_angle, &rd->arc);
	case KW_FALLOFF_ANGLE: return rainbow_angle(e, item, &r->falloff_angle, &rd->falloff);
	default: return 1;
	}
}

static int rainbow_item(struct eval *e, struct cursor *c, const ast_node *item, struct rainbow_read *rd)
{
	int rc;
	if (item->kind == AST_ARG && (rc = rainbow_arg(e, item, rd)) <= 0)
		return rc;
	if (item->kind == AST_BLOCK && (item->kw == KW_COLOR_MAP || item->kw == KW_COLOUR_MAP))
		return rainbow_map(e, item, &rd->r);
	if (item->kind == AST_FLAG && item->kw == KW_JITTER) {   /* jitter F */
		int err = 0;
		const ast_node *x = eval_next_expr(c, &err);
		if (err || !x) {
			if (!err)
				eval_error(e, item->loc, "a rainbow's jitter needs an amount: jitter 0.01");
			return -1;
		}
		return eval_expect_float(e, x, &rd->r.jitter);
	}
	return eval_not_valid(e, item, "a rainbow");
}

/* What Parse_Rainbow does after the items: the falloff angle, the checks,
 * up made square to the direction (the direction stays as written), the
 * angles into radians with angle moved to the band's inner edge. */
static int rainbow_finish(struct eval *e, const ast_node *b, struct rainbow_read *rd)
{
	scene_rainbow *r = &rd->r;
	if (rd->arc && !rd->falloff)
		r->falloff_angle = r->arc_angle;
	const char *bad = r->arc_angle < r->falloff_angle ? "its arc_angle is smaller than its falloff_angle"
	                  : fabs(vec3_dot(r->direction, r->direction)) < RAINBOW_EPSILON ? "its direction is <0, 0, 0>"
	                  : fabs(vec3_dot(r->up, r->up)) < RAINBOW_EPSILON ? "its up vector is <0, 0, 0>" : NULL;
	if (!bad) {
		vec3_normalize(r->direction);
		vec3_normalize(r->up);
		if (fabs(1 - fabs(vec3_dot(r->up, r->direction))) < RAINBOW_EPSILON)
			bad = "its up vector and its direction are parallel";
	}
	if (bad) {
		eval_error(e, b->loc, "a rainbow cannot be made: %s", bad);
		return -1;
	}
	vec3_cross(r->up, r->direction, r->right);
	vec3_cross(r->direction, r->right, r->up);
	vec3_normalize(r->up);
	vec3_normalize(r->right);
	r->angle = (r->angle - 0.5 * r->width) * M_PI / 180;
	r->width *= M_PI / 180;
	return 0;
}

/* rainbow { direction <V> angle A width W [distance D] color_map { ... }
 *           [jitter J] [up <U>] [arc_angle AA] [falloff_angle FA] } */
int eval_rainbow_statement(struct eval *e, const ast_node *b)
{
	struct rainbow_read rd = { .r = rainbow_default(b->loc) };
	struct cursor c;
	int err = 0, rc = 0;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL)
		rc = rainbow_item(e, &c, item, &rd);
	eval_cursor_free(&c);
	if (rc || err || rainbow_finish(e, b, &rd))
		return -1;
	/* ComputeRainbow passes over a rainbow without these */
	if (rd.r.pigment < 0 || rd.r.distance == 0 || rd.r.width == 0)
		eval_warning(e, b->loc, "a rainbow without %s has no effect",
		             rd.r.pigment < 0 ? "a colour_map" : rd.r.distance == 0 ? "a distance" : "a width");
	else
		scene_add_rainbow(e->s, &rd.r);
	return 0;
}
