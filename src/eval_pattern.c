/* eval_pattern.c: the patterns of pigments, their modifiers and warps, read into
 * a scene_pigment (scene.h) that lowering turns into a dev_pattern and the
 * kernels evaluate at each shading point (kernels/pattern.cl, texture.cl).
 *
 * A new pattern is a name in the table below (and PATTERN_ in shared.h), its
 * POV-Ray defaults in pattern_defaults, its parameters in pattern_modifier when
 * it has any, and its case in kernels/pattern.cl. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"

int eval_pattern_kind(const char *name)
{
	for (int k = 1; k < PATTERN_COUNT; k++)
		if (strcmp(scene_pattern_name(k), name) == 0)
			return k;
	return -1;
}

/* The colours a discrete pattern lists (checker A, B), 0 for continuous ones. */
int eval_pattern_list_size(int kind)
{
	switch (kind) {
	case PATTERN_CHECKER: case PATTERN_BRICK: return 2;
	case PATTERN_HEXAGON: return 3;
	case PATTERN_SQUARE: return 4;
	case PATTERN_CUBIC: case PATTERN_TRIANGULAR: return 6;
	default: return 0;
	}
}

/* POV-Ray 3.7's defaults for a pattern's modifiers. */
void eval_pattern_defaults(scene_pigment *pg, int kind, src_loc loc)
{
	*pg = (scene_pigment){ .kind = kind, .wave = WAVE_RAMP, .noise_generator = 2, .frequency = 1,
	                       .wave_exponent = 1, .xf = scene_xform_identity(), .loc = loc };
	double *p = pg->params[0];
	switch (kind) {
	case PATTERN_AGATE: p[0] = 1; break;
	case PATTERN_BRICK: p[0] = 8; p[1] = 3; p[2] = 4.5; p[3] = 0.5; break;
	case PATTERN_CRACKLE: p[0] = -1; p[1] = 1; p[2] = 0; p[3] = 2; break;
	case PATTERN_QUILTED: p[0] = 1; p[1] = 1; break;
	case PATTERN_GRADIENT: p[0] = 1; break;
	case PATTERN_SPIRAL1: case PATTERN_SPIRAL2: p[0] = 1; break;
	default: break;
	}
}

/* POV-Ray's default colours of a discrete pattern without a list, and the
 * colour map of a continuous one without a map. */
void eval_pattern_default_map(scene_pigment *pg)
{
	static const float discrete[6][5] = {
		{ 0, 0, 1, 0, 0 }, { 0, 1, 0, 0, 0 }, { 1, 0, 0, 0, 0 },
		{ 1, 1, 0, 0, 0 }, { 0, 1, 1, 0, 0 }, { 1, 0, 1, 0, 0 },
	};
	/* POV-Ray's default colour_map: a rainbow over 0 to 1. */
	static const float rainbow[6][5] = {
		{ 1, 0, 0, 0, 0 }, { 1, 1, 0, 0, 0 }, { 0, 1, 0, 0, 0 },
		{ 0, 1, 1, 0, 0 }, { 0, 0, 1, 0, 0 }, { 1, 0, 1, 0, 0 },
	};
	int n = eval_pattern_list_size(pg->kind);
	if (pg->kind == PATTERN_BRICK) {   /* mortar white, brick red */
		static const float brick[2][5] = { { 1, 1, 1, 0, 0 }, { 1, 0, 0, 0, 0 } };
		pg->map = eval_xrealloc(NULL, 2 * sizeof *pg->map);
		for (int i = 0; i < 2; i++)
			pg->map[i] = (scene_map_entry){ .value = i, .pigment = -1 };
		memcpy(pg->map[0].colour, brick[0], sizeof brick[0]);
		memcpy(pg->map[1].colour, brick[1], sizeof brick[1]);
		pg->n_map = 2;
		return;
	}
	const float (*c)[5] = n ? discrete : rainbow;
	int count = n ? n : 6;
	pg->map = eval_xrealloc(NULL, count * sizeof *pg->map);
	for (int i = 0; i < count; i++) {
		pg->map[i] = (scene_map_entry){ .value = n ? i : i / 5.0, .pigment = -1 };
		memcpy(pg->map[i].colour, c[i], sizeof c[i]);
	}
	pg->n_map = count;
}

/* ---- modifiers ---- */

/* The word an item is, when it is an undeclared identifier (metric, form...). */
static const char *word(struct eval *e, const ast_node *item)
{
	return item->kind == AST_IDENT && !eval_lookup(e, item->str) ? item->str : NULL;
}

static int next_float(struct eval *e, struct cursor *c, const ast_node *at, double *out)
{
	int err = 0;
	const ast_node *arg = eval_next_expr(c, &err);
	if (!arg) {
		if (!err)
			eval_error(e, at->loc, "'%s' needs a value", at->str ? at->str : ast_keyword_name(at->kw));
		return -1;
	}
	return eval_expect_float(e, arg, out);
}

static int next_vector(struct eval *e, struct cursor *c, const ast_node *at, double out[3])
{
	int err = 0;
	const ast_node *arg = eval_next_expr(c, &err);
	if (!arg) {
		if (!err)
			eval_error(e, at->loc, "'%s' needs a vector", at->str ? at->str : ast_keyword_name(at->kw));
		return -1;
	}
	return eval_expect_vector(e, arg, out);
}

/* The argument of an AST_ARG item: a float, or a vector into out. */
static int arg_float(struct eval *e, const ast_node *item, double *out)
{
	return eval_expect_float(e, item->kids[0], out);
}

/* The classic turbulence warp: the first, made when the pattern has none. */
static scene_warp *classic_turb(struct eval *e, scene_pigment *pg, src_loc loc)
{
	if (pg->turb_first)
		return &pg->warps[0];
	if (pg->n_warps == SCENE_MAX_WARPS) {
		eval_error(e, loc, "a pattern takes at most %d warps", SCENE_MAX_WARPS);
		return NULL;
	}
	memmove(pg->warps + 1, pg->warps, pg->n_warps * sizeof *pg->warps);
	pg->n_warps++;
	pg->turb_first = true;
	/* POV-Ray's defaults: octaves 6, omega 0.5, lambda 2 */
	pg->warps[0] = (scene_warp){ .kind = WARP_TURBULENCE, .a = { 0, 0, 0, 0.5 }, .b = { 2, 6 } };
	return &pg->warps[0];
}

/* turbulence, octaves, omega, lambda: of w, a turbulence warp. 1: not one. */
static int turbulence_item(struct eval *e, const ast_node *item, scene_warp *w)
{
	if (item->kind != AST_ARG)
		return 1;
	double v[3];
	switch (item->kw) {
	case KW_TURBULENCE:
		if (eval_expect_vector(e, item->kids[0], v))
			return -1;
		memcpy(w->a, v, sizeof v);
		return 0;
	case KW_OCTAVES: return arg_float(e, item, &w->b[1]);
	case KW_OMEGA: return arg_float(e, item, &w->a[3]);
	case KW_LAMBDA: return arg_float(e, item, &w->b[0]);
	default: return 1;
	}
}

/* warp { turbulence ... | repeat <V> [offset <V>] [flip <V>] |
 *        black_hole <Centre>, Radius [strength S] [falloff F] [inverse] [repeat <V>] } */
static int warp_block(struct eval *e, const ast_node *b, scene_pigment *pg)
{
	if (pg->n_warps == SCENE_MAX_WARPS) {
		eval_error(e, b->loc, "a pattern takes at most %d warps", SCENE_MAX_WARPS);
		return -1;
	}
	scene_warp w = { .kind = -1 };
	struct cursor c;
	int err = 0, rc = 0;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		const char *name = word(e, item);
		if (w.kind < 0 && item->kind == AST_ARG && item->kw == KW_TURBULENCE)
			w = (scene_warp){ .kind = WARP_TURBULENCE, .a = { 0, 0, 0, 0.5 }, .b = { 2, 6 } };
		if (w.kind == WARP_TURBULENCE && (rc = turbulence_item(e, item, &w)) <= 0)
			continue;
		rc = 0;
		if (name && strcmp(name, "repeat") == 0 && w.kind < 0) {
			w = (scene_warp){ .kind = WARP_REPEAT };
			rc = next_vector(e, &c, item, w.a);
		} else if (name && strcmp(name, "black_hole") == 0 && w.kind < 0) {
			w = (scene_warp){ .kind = WARP_BLACK_HOLE, .b = { 1, 0, 0 } };
			rc = next_vector(e, &c, item, w.a) || next_float(e, &c, item, &w.a[3]) ? -1 : 0;
		} else if (name && strcmp(name, "offset") == 0 && w.kind == WARP_REPEAT) {
			rc = next_vector(e, &c, item, w.b);
		} else if (name && strcmp(name, "flip") == 0 && w.kind == WARP_REPEAT) {
			rc = next_vector(e, &c, item, w.c);
		} else if (name && strcmp(name, "strength") == 0 && w.kind == WARP_BLACK_HOLE) {
			rc = next_float(e, &c, item, &w.b[0]);
		} else if (item->kind == AST_ARG && item->kw == KW_FALLOFF && w.kind == WARP_BLACK_HOLE) {
			rc = arg_float(e, item, &w.b[1]);
		} else if (item->kind == AST_FLAG && item->kw == KW_INVERSE && w.kind == WARP_BLACK_HOLE) {
			w.b[2] = 1;
		} else if (name && strcmp(name, "repeat") == 0 && w.kind == WARP_BLACK_HOLE) {
			rc = next_vector(e, &c, item, w.c);
			w.c[3] = 1;
		} else {
			rc = eval_not_valid(e, item, "a warp");
		}
	}
	eval_cursor_free(&c);
	if (rc || err)
		return -1;
	if (w.kind < 0) {
		eval_warning(e, b->loc, "an empty warp is ignored");
		return 0;
	}
	if (w.kind == WARP_BLACK_HOLE && w.b[1] == 0)
		w.b[1] = w.b[0];   /* POV-Ray: falloff defaults to strength... and 0 radius stays 0 */
	pg->warps[pg->n_warps++] = w;
	return 0;
}

static int set_wave(scene_pigment *pg, int wave)
{
	pg->wave = wave;
	return 0;
}

/* A modifier of a pattern in a pigment: its own parameters (brick_size, metric...),
 * turbulence, the waves, frequency, phase, warps. Returns 0 when item was one,
 * 1 when not, -1 after an error. */
int eval_pattern_modifier(struct eval *e, struct cursor *c, const ast_node *item, scene_pigment *pg)
{
	double *p0 = pg->params[0], *p1 = pg->params[1];
	if (item->kind == AST_ARG) {
		switch (item->kw) {
		case KW_TURBULENCE: case KW_OCTAVES: case KW_OMEGA: case KW_LAMBDA: {
			scene_warp *w = classic_turb(e, pg, item->loc);
			return w ? turbulence_item(e, item, w) : -1;
		}
		case KW_FREQUENCY: return arg_float(e, item, &pg->frequency);
		case KW_PHASE: return arg_float(e, item, &pg->phase);
		case KW_AGATE_TURB: return arg_float(e, item, &p0[0]);
		case KW_MORTAR: return arg_float(e, item, &p0[3]);
		case KW_BRICK_SIZE: {
			double v[3];
			if (eval_expect_vector(e, item->kids[0], v))
				return -1;
			memcpy(p0, v, sizeof v);
			return 0;
		}
		default: return 1;
		}
	}
	if (item->kind == AST_FLAG) {
		switch (item->kw) {
		case KW_RAMP_WAVE: return set_wave(pg, WAVE_RAMP);
		case KW_SINE_WAVE: return set_wave(pg, WAVE_SINE);
		case KW_TRIANGLE_WAVE: return set_wave(pg, WAVE_TRIANGLE);
		case KW_SCALLOP_WAVE: return set_wave(pg, WAVE_SCALLOP);
		case KW_CUBIC_WAVE: return set_wave(pg, WAVE_CUBIC);
		case KW_POLY_WAVE: {
			int err = 0;
			const ast_node *arg = eval_next_expr(c, &err);
			pg->wave = WAVE_POLY;
			return arg ? eval_expect_float(e, arg, &pg->wave_exponent) : err ? -1 : 0;
		}
		default: return 1;
		}
	}
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && strcmp(item->str, "warp") == 0)
		return warp_block(e, item, pg);
	const char *name = word(e, item);
	if (!name)
		return 1;
	double v[3];
	if (strcmp(name, "noise_generator") == 0) {
		double g;
		if (next_float(e, c, item, &g))
			return -1;
		if (g < 1 || g > 3) {
			eval_error(e, item->loc, "noise_generator is 1, 2 or 3");
			return -1;
		}
		pg->noise_generator = (int)g;
		return 0;
	}
	if (pg->kind == PATTERN_CRACKLE && strcmp(name, "metric") == 0)
		return next_float(e, c, item, &p0[3]);
	if (pg->kind == PATTERN_CRACKLE && strcmp(name, "form") == 0) {
		if (next_vector(e, c, item, v))
			return -1;
		memcpy(p0, v, sizeof v);
		return 0;
	}
	if (pg->kind == PATTERN_CRACKLE && strcmp(name, "offset") == 0)
		return next_float(e, c, item, &p1[0]);
	if (pg->kind == PATTERN_CRACKLE && strcmp(name, "solid") == 0) {
		p1[1] = 1;
		return 0;
	}
	if (pg->kind == PATTERN_QUILTED && strcmp(name, "control0") == 0)
		return next_float(e, c, item, &p0[0]);
	if (pg->kind == PATTERN_QUILTED && strcmp(name, "control1") == 0)
		return next_float(e, c, item, &p0[1]);
	return 1;
}

/* The argument a pattern keyword takes: gradient's axis, spiral's arms. */
int eval_pattern_argument(struct eval *e, const ast_node *item, scene_pigment *pg)
{
	if (item->kind != AST_ARG)
		return 0;
	if (pg->kind == PATTERN_GRADIENT) {
		double v[3];
		if (eval_expect_vector(e, item->kids[0], v))
			return -1;
		memcpy(pg->params[0], v, sizeof v);
		return 0;
	}
	return arg_float(e, item, &pg->params[0][0]);
}
