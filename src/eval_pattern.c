/* eval_pattern.c: the patterns of pigments, their modifiers and warps, read into
 * a scene_pigment (scene.h) that lowering turns into a dev_pattern and the
 * kernels evaluate at each shading point (kernels/pattern.cl, texture.cl).
 *
 * A new pattern is a name in the table below (and PATTERN_ in shared.h), its
 * POV-Ray defaults in pattern_defaults, its parameters in pattern_modifier when
 * it has any (checks that need all of them at the end, as pavement's), and its
 * case in kernels/pattern.cl. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"
#include "image.h"

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
	case PATTERN_CHECKER: case PATTERN_BRICK: case PATTERN_OBJECT: return 2;
	case PATTERN_HEXAGON: return 3;
	case PATTERN_SQUARE: return 4;
	case PATTERN_CUBIC: case PATTERN_TRIANGULAR: return 6;
	default: return 0;
	}
}

/* POV-Ray 3.7's defaults for a pattern's modifiers. */
void eval_pattern_defaults(scene_pigment *pg, int kind, src_loc loc)
{
	*pg = (scene_pigment){ .kind = kind, .wave = WAVE_RAMP, .frequency = 1,
	                       .wave_exponent = 1, .loc = loc };
	double *p = pg->params[0];
	switch (kind) {
	case PATTERN_AGATE:   /* POV-Ray gives agate a classic turbulence, of 0 */
		p[0] = 1;
		pg->warps[pg->n_warps++] = (scene_warp){ .kind = WARP_TURBULENCE, .classic = true, .a = { 0, 0, 0, 0.5 },
		                                         .b = { 2, 6 } };
		break;
	case PATTERN_MARBLE: case PATTERN_WOOD: pg->wave = WAVE_TRIANGLE; break;
	case PATTERN_QUILTED: pg->frequency = 0; p[0] = 1; p[1] = 1; break;
	case PATTERN_OBJECT: pg->frequency = 0; p[0] = -1; break;   /* its object: eval_pattern_object */
	case PATTERN_BRICK: p[0] = 8; p[1] = 3; p[2] = 4.5; p[3] = 0.5; break;
	case PATTERN_CRACKLE: p[0] = -1; p[1] = 1; p[2] = 0; p[3] = 2; break;
	case PATTERN_GRADIENT: p[0] = 1; break;
	case PATTERN_PAVEMENT: p[0] = 3; p[1] = 1; p[2] = 1; break;   /* form, interior, exterior 0 */
	case PATTERN_SPIRAL1: case PATTERN_SPIRAL2: p[0] = 1; pg->wave = WAVE_TRIANGLE; break;
	case PATTERN_MANDEL: case PATTERN_JULIA: case PATTERN_MAGNET: eval_fractal_defaults(pg); break;
	default: break;
	}
}

/* POV-Ray 3.7's default maps: a pattern without a map or a list of its own
 * uses its kind's (value, colour) entries, black to white for most. Discrete
 * patterns look their index up in them as in any map, so cubic's default
 * (0, 1, 1, 1, 1, 2) shows red, green and then magenta, as in POV-Ray. */
struct default_entry {
	float value, rgb[3];
};
static const struct default_entry map_grey[] = { { 0, { 0, 0, 0 } }, { 1, { 1, 1, 1 } } };
static const struct default_entry map_agate[] = {
	{ 0, { 1, 1, 1 } }, { 0.5f, { 0.95f, 0.75f, 0.5f } }, { 0.5f, { 0.9f, 0.7f, 0.5f } },
	{ 0.6f, { 0.9f, 0.7f, 0.4f } }, { 0.6f, { 1, 0.7f, 0.4f } }, { 1, { 0.6f, 0.3f, 0 } },
};
static const struct default_entry map_bozo[] = {
	{ 0.4f, { 1, 1, 1 } }, { 0.4f, { 0, 1, 0 } }, { 0.6f, { 0, 1, 0 } },
	{ 0.6f, { 0, 0, 1 } }, { 0.8f, { 0, 0, 1 } }, { 0.8f, { 1, 0, 0 } },
};
static const struct default_entry map_brick[] = { { 0, { 0.5f, 0.5f, 0.5f } }, { 1, { 0.6f, 0.15f, 0.15f } } };
static const struct default_entry map_checker[] = { { 0, { 0, 0, 1 } }, { 1, { 0, 1, 0 } } };
static const struct default_entry map_six[] = {   /* cubic, triangular */
	{ 0, { 1, 0, 0 } }, { 1, { 0, 1, 0 } }, { 1, { 0, 0, 1 } }, { 1, { 1, 1, 0 } }, { 1, { 0, 1, 1 } },
	{ 2, { 1, 0, 1 } },
};
static const struct default_entry map_hexagon[] = { { 0, { 0, 0, 1 } }, { 1, { 0, 1, 0 } }, { 2, { 1, 0, 0 } } };
static const struct default_entry map_mandel[] = {
	{ 0.001f, { 0, 0, 0 } }, { 0.001f, { 0, 1, 1 } }, { 0.012f, { 1, 1, 0 } }, { 0.015f, { 1, 0, 1 } },
	{ 0.1f, { 0, 1, 1 } },
};
static const struct default_entry map_marble[] = {
	{ 0, { 0.9f, 0.8f, 0.8f } }, { 0.9f, { 0.9f, 0.08f, 0.08f } }, { 0.9f, { 0, 0, 0 } },
};
static const struct default_entry map_radial[] = {
	{ 0, { 0, 1, 1 } }, { 0.333f, { 1, 1, 0 } }, { 0.666f, { 1, 0, 1 } }, { 1, { 0, 1, 1 } },
};
static const struct default_entry map_wood[] = {
	{ 0.6f, { 0.666f, 0.312f, 0.2f } }, { 0.6f, { 0.4f, 0.1333f, 0.066f } },
};

void eval_pattern_default_map(scene_pigment *pg)
{
#define MAP(M) (m = M, n = (int)(sizeof M / sizeof *M))
	const struct default_entry *m;
	int n;
	switch (pg->kind) {
	case PATTERN_AGATE: MAP(map_agate); break;
	case PATTERN_BOZO: MAP(map_bozo); break;
	case PATTERN_BRICK: MAP(map_brick); break;
	case PATTERN_CHECKER: case PATTERN_OBJECT: MAP(map_checker); break;   /* object: POV-Ray's Check_Default_Map */
	case PATTERN_CUBIC: case PATTERN_TRIANGULAR: MAP(map_six); break;
	case PATTERN_SQUARE: m = map_six, n = 4; break;   /* POV-Ray's square uses its first four */
	case PATTERN_HEXAGON: MAP(map_hexagon); break;
	case PATTERN_MARBLE: MAP(map_marble); break;
	case PATTERN_MANDEL:   /* POV-Ray gives exponent 2 alone its own map */
		if (pg->params[0][1] == 2)
			MAP(map_mandel);
		else
			MAP(map_grey);
		break;
	case PATTERN_RADIAL: MAP(map_radial); break;
	case PATTERN_WOOD: MAP(map_wood); break;
	default: MAP(map_grey); break;
	}
#undef MAP
	pg->map = eval_xrealloc(NULL, n * sizeof *pg->map);
	for (int i = 0; i < n; i++)
		pg->map[i] = (scene_map_entry){ .value = m[i].value, .colour = { m[i].rgb[0], m[i].rgb[1], m[i].rgb[2] },
		                                .pigment = -1 };
	pg->n_map = n;
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

static int room(struct eval *e, const scene_pigment *pg, src_loc loc)
{
	if (pg->n_warps < SCENE_MAX_WARPS)
		return 0;
	eval_error(e, loc, "a pattern takes at most %d warps and transformations between them", SCENE_MAX_WARPS);
	return -1;
}

/* POV-Ray's list of warps: a warp { } goes to its front, so the last written
 * applies first. */
static void push_front(scene_pigment *pg, const scene_warp *w)
{
	memmove(pg->warps + 1, pg->warps, pg->n_warps * sizeof *pg->warps);
	pg->warps[0] = *w;
	pg->n_warps++;
}

/* The classic turbulence (written in the pattern, not in a warp): made at the
 * end of the list the first time, with POV-Ray's octaves 6, omega 0.5, lambda 2. */
static scene_warp *classic_turb(struct eval *e, scene_pigment *pg, src_loc loc)
{
	for (int i = 0; i < pg->n_warps; i++)
		if (pg->warps[i].kind == WARP_TURBULENCE && pg->warps[i].classic)
			return &pg->warps[i];
	if (room(e, pg, loc))
		return NULL;
	pg->warps[pg->n_warps] = (scene_warp){ .kind = WARP_TURBULENCE, .classic = true, .a = { 0, 0, 0, 0.5 },
	                                       .b = { 2, 6 } };
	return &pg->warps[pg->n_warps++];
}

/* A transformation written in a pigment: it joins the front of the list when
 * that is a transformation, else it becomes the new front. */
int eval_pattern_transform(struct eval *e, scene_pigment *pg, const xform *t, src_loc loc)
{
	if (pg->n_warps > 0 && pg->warps[0].kind == WARP_TRANSFORM) {
		pg->warps[0].xf = scene_xform_then(&pg->warps[0].xf, t);
		return 0;
	}
	if (room(e, pg, loc))
		return -1;
	push_front(pg, &(scene_warp){ .kind = WARP_TRANSFORM, .xf = *t });
	return 0;
}

/* POV-Ray's pigment { PATTERN } where a texture already has a pigment: the
 * parser reuses the old pigment's list of warps, so the new pattern keeps the
 * warps and transformations the old one had (its own, then the texture's
 * since, t) and adds its own in front. Both go to the back of pg's list; a
 * classic turbulence of the old list yields to one the new pattern wrote, as
 * POV-Ray keeps only one. */
int eval_pattern_continue(struct eval *e, scene_pigment *pg, const scene_pigment *old, const xform *t,
                          src_loc loc)
{
	bool classic = false;
	for (int i = 0; i < pg->n_warps; i++)
		classic |= pg->warps[i].kind == WARP_TURBULENCE && pg->warps[i].classic;
	xform id = scene_xform_identity();
	if (memcmp(t, &id, sizeof id) != 0) {
		if (room(e, pg, loc))
			return -1;
		pg->warps[pg->n_warps++] = (scene_warp){ .kind = WARP_TRANSFORM, .xf = *t };
	}
	for (int i = 0; old && i < old->n_warps; i++) {
		if (classic && old->warps[i].kind == WARP_TURBULENCE && old->warps[i].classic)
			continue;
		if (room(e, pg, loc))
			return -1;
		pg->warps[pg->n_warps++] = old->warps[i];
	}
	return 0;
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

/* An orientation vector, made a unit one as POV-Ray does. */
static int orientation(struct eval *e, struct cursor *c, const ast_node *at, const ast_node *arg, double a[4])
{
	double v[3];
	if ((arg ? eval_expect_vector(e, arg, v) : next_vector(e, c, at, v)) != 0)
		return -1;
	double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
	if (!(l > 0) || !isfinite(l)) {
		eval_error(e, (arg ? arg : at)->loc, "a warp's orientation must be a vector other than <0, 0, 0>");
		return -1;
	}
	for (int k = 0; k < 3; k++)
		a[k] = v[k] / l;
	return 0;
}

/* planar [<Orientation>, Offset] | cylindrical | spherical | toroidal | cubic:
 * the warp begun, with POV-Ray's defaults (Create_Warp): orientation
 * <0, 0, 1>, dist_exp 0, major_radius 1. */
static int mapping_warp(struct eval *e, struct cursor *c, const ast_node *item, const char *mapping, scene_warp *w)
{
	static const char *const names[] = { "planar", "cylindrical", "spherical", AST_WORD_TOROIDAL, AST_WORD_CUBIC };
	*w = (scene_warp){ .kind = WARP_PLANAR, .a = { 0, 0, 1, 0 }, .b = { 1 } };
	for (int k = 0; k < 5; k++)
		if (strcmp(mapping, names[k]) == 0)
			w->kind = WARP_PLANAR + k;
	if (w->kind != WARP_PLANAR)
		return 0;
	int err = 0;
	const ast_node *v = eval_next_expr(c, &err);
	if (err)
		return -1;
	return v && (orientation(e, c, item, v, w->a) || next_float(e, c, item, &w->a[3])) ? -1 : 0;
}

/* orientation <V>, dist_exp F, and a toroidal warp's major_radius F. 1: none of them. */
static int mapping_item(struct eval *e, struct cursor *c, const ast_node *item, const char *name, scene_warp *w)
{
	if (!name)
		return 1;
	if (strcmp(name, AST_WORD_ORIENTATION) == 0)
		return orientation(e, c, item, NULL, w->a);
	if (strcmp(name, AST_WORD_DIST_EXP) == 0)
		return next_float(e, c, item, &w->a[3]);
	if (strcmp(name, AST_WORD_MAJOR_RADIUS) == 0 && w->kind == WARP_TOROIDAL)
		return next_float(e, c, item, &w->b[0]);
	return 1;
}

/* warp { turbulence ... | repeat <V> [offset <V>] [flip <V>] |
 *        black_hole <Centre>, Radius [strength S] [falloff F] [inverse] [repeat <V>]
 *        [turbulence <V>] } */
static int warp_block(struct eval *e, const ast_node *b, scene_pigment *pg)
{
	if (room(e, pg, b->loc))
		return -1;
	scene_warp w = { .kind = -1 };
	struct cursor c;
	int err = 0, rc = 0;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		const char *name = word(e, item);
		const char *mapping = item->kind == AST_FLAG && (item->kw == KW_PLANAR || item->kw == KW_SPHERICAL ||
		                      item->kw == KW_CYLINDRICAL) ? ast_keyword_name(item->kw)
		                    : name && (strcmp(name, AST_WORD_TOROIDAL) == 0 || strcmp(name, AST_WORD_CUBIC) == 0) ? name : NULL;
		if (w.kind < 0 && mapping) {   /* POV-Ray 3.7's mapping warps */
			rc = mapping_warp(e, &c, item, mapping, &w);
			continue;
		}
		if (w.kind > WARP_PLANAR && w.kind < WARP_CUBIC && (rc = mapping_item(e, &c, item, name, &w)) <= 0)
			continue;
		rc = 0;
		if (w.kind < 0 && item->kind == AST_ARG && item->kw == KW_TURBULENCE)
			w = (scene_warp){ .kind = WARP_TURBULENCE, .a = { 0, 0, 0, 0.5 }, .b = { 2, 6 } };
		if (w.kind == WARP_TURBULENCE && (rc = turbulence_item(e, item, &w)) <= 0)
			continue;
		rc = 0;
		if (name && strcmp(name, AST_WORD_REPEAT) == 0 && w.kind < 0) {
			w = (scene_warp){ .kind = WARP_REPEAT };
			rc = next_vector(e, &c, item, w.a);
		} else if (name && strcmp(name, AST_WORD_BLACK_HOLE) == 0 && w.kind < 0) {
			w = (scene_warp){ .kind = WARP_BLACK_HOLE, .b = { 1, 2, 0 } };   /* strength 1, falloff 2 */
			rc = next_vector(e, &c, item, w.a) || next_float(e, &c, item, &w.a[3]) ? -1 : 0;
		} else if (name && strcmp(name, AST_WORD_OFFSET) == 0 && w.kind == WARP_REPEAT) {
			rc = next_vector(e, &c, item, w.b);
		} else if (name && strcmp(name, AST_WORD_FLIP) == 0 && w.kind == WARP_REPEAT) {
			rc = next_vector(e, &c, item, w.c);
		} else if (name && strcmp(name, AST_WORD_STRENGTH) == 0 && w.kind == WARP_BLACK_HOLE) {
			rc = next_float(e, &c, item, &w.b[0]);
		} else if (item->kind == AST_ARG && item->kw == KW_FALLOFF && w.kind == WARP_BLACK_HOLE) {
			rc = arg_float(e, item, &w.b[1]);
		} else if (item->kind == AST_FLAG && item->kw == KW_INVERSE && w.kind == WARP_BLACK_HOLE) {
			w.b[2] = 1;
		} else if (name && strcmp(name, AST_WORD_REPEAT) == 0 && w.kind == WARP_BLACK_HOLE) {
			rc = next_vector(e, &c, item, w.c);
			w.c[3] = 1;
		} else if (item->kind == AST_ARG && item->kw == KW_TURBULENCE && w.kind == WARP_BLACK_HOLE) {
			rc = eval_expect_vector(e, item->kids[0], w.d);   /* jitters the repeated holes */
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
	if (w.kind == WARP_BLACK_HOLE && w.c[3] != 0)   /* POV-Ray keeps a repeated hole inside its block */
		for (int k = 0; k < 3; k++) {
			if (!(w.c[k] > 0))
				continue;
			if (w.a[k] < w.a[3])
				w.a[k] = w.a[3];
			if (w.c[k] < w.a[k] + w.a[3] + w.d[k]) {   /* and its jitter too: the block grows */
				w.c[k] = w.a[k] + w.a[3] + w.d[k];
				eval_warning(e, b->loc, "the black hole's repeat along %c is too small for its centre, radius "
				             "and turbulence: increased to %g, as POV-Ray does", "xyz"[k], w.c[k]);
			}
			if (w.c[k] < 1e-10)   /* POV-Ray's EPSILON: no repeat along that axis */
				w.c[k] = 0;
		}
	push_front(pg, &w);
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
	int rc = eval_pattern_is_fractal(pg->kind) ? eval_fractal_modifier(e, c, item, pg) : 1;
	if (rc <= 0)
		return rc;
	if (item->kind == AST_ARG && item->kw == KW_INTERIOR) {   /* the fractals' came first */
		if (pg->kind == PATTERN_PAVEMENT)
			return arg_float(e, item, &p1[0]);
		eval_error(e, item->loc, "'interior' is only valid in mandel, julia, magnet or pavement");
		return -1;
	}
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
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && strcmp(item->str, AST_WORD_WARP) == 0)
		return warp_block(e, item, pg);
	const char *name = word(e, item);
	if (!name)
		return 1;
	double v[3];
	if (strcmp(name, AST_WORD_NO_BUMP_SCALE) == 0) {
		pg->no_bump_scale = true;
		return 0;
	}
	if (strcmp(name, AST_WORD_INTERPOLATE) == 0 && pg->kind == PATTERN_DENSITY_FILE) {
		int err = 0;
		const ast_node *arg = eval_next_expr(c, &err);
		if (!arg && !err)
			eval_error(e, item->loc, "'interpolate' needs a value");
		return arg ? eval_density_file_interpolate(e, arg, pg) : -1;
	}
	if (strcmp(name, AST_WORD_NOISE_GENERATOR) == 0) {
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
	if (pg->kind == PATTERN_CRACKLE && strcmp(name, AST_WORD_METRIC) == 0)
		return next_float(e, c, item, &p0[3]);
	if (pg->kind == PATTERN_CRACKLE && strcmp(name, AST_WORD_FORM) == 0) {
		if (next_vector(e, c, item, v))
			return -1;
		memcpy(p0, v, sizeof v);
		return 0;
	}
	if (pg->kind == PATTERN_CRACKLE && strcmp(name, AST_WORD_OFFSET) == 0)
		return next_float(e, c, item, &p1[0]);
	if (pg->kind == PATTERN_CRACKLE && strcmp(name, AST_WORD_SOLID) == 0) {
		p1[1] = 1;
		return 0;
	}
	if (pg->kind != PATTERN_PAVEMENT && (strcmp(name, AST_WORD_NUMBER_OF_SIDES) == 0 ||
	    strcmp(name, AST_WORD_NUMBER_OF_TILES) == 0 || strcmp(name, AST_WORD_PATTERN) == 0 ||
	    strcmp(name, AST_WORD_EXTERIOR) == 0)) {   /* POV-Ray's Only_In */
		eval_error(e, item->loc, "'%s' is only valid in %s", name,
		           strcmp(name, AST_WORD_EXTERIOR) == 0 ? "mandel, julia, magnet or pavement" : "pavement");
		return -1;
	}
	if (pg->kind == PATTERN_PAVEMENT && strcmp(name, AST_WORD_NUMBER_OF_SIDES) == 0)
		return next_float(e, c, item, &p0[0]);
	if (pg->kind == PATTERN_PAVEMENT && strcmp(name, AST_WORD_NUMBER_OF_TILES) == 0)
		return next_float(e, c, item, &p0[1]);
	if (pg->kind == PATTERN_PAVEMENT && strcmp(name, AST_WORD_PATTERN) == 0)
		return next_float(e, c, item, &p0[2]);
	if (pg->kind == PATTERN_PAVEMENT && strcmp(name, AST_WORD_FORM) == 0)
		return next_float(e, c, item, &p0[3]);
	if (pg->kind == PATTERN_PAVEMENT && strcmp(name, AST_WORD_EXTERIOR) == 0)
		return next_float(e, c, item, &p1[1]);
	if (pg->kind == PATTERN_QUILTED && strcmp(name, AST_WORD_CONTROL0) == 0)
		return next_float(e, c, item, &p0[0]);
	if (pg->kind == PATTERN_QUILTED && strcmp(name, AST_WORD_CONTROL1) == 0)
		return next_float(e, c, item, &p0[1]);
	return 1;
}

/* The argument a pattern keyword takes: gradient's axis, spiral's arms. */
int eval_pattern_argument(struct eval *e, const ast_node *item, scene_pigment *pg)
{
	if (item->kind != AST_ARG)
		return 0;
	if (pg->kind == PATTERN_GRADIENT) {   /* the axis, normalized as POV-Ray does */
		double v[3];
		if (eval_expect_vector(e, item->kids[0], v))
			return -1;
		double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
		for (int k = 0; k < 3; k++)
			pg->params[0][k] = len > 0 ? v[k] / len : 0;
		return 0;
	}
	return arg_float(e, item, &pg->params[0][0]);
}

/* tiling N: POV-Ray 3.7 keeps N as an unsigned char (its integer part modulo
 * 256, as x86 converts it: 259 is tiling 3) and refuses what is not then 1 to
 * 27. */
int eval_pattern_tiling(struct eval *e, struct cursor *c, const ast_node *item, scene_pigment *pg)
{
	int err = 0;
	double n;
	const ast_node *arg = eval_next_expr(c, &err);
	if (!arg) {
		if (!err)
			eval_error(e, item->loc, "'tiling' needs its number, 1 to 27");
		return -1;
	}
	if (eval_expect_float(e, arg, &n))
		return -1;
	long code = fabs(n) < 2e9 ? ((long)n & 255) : 0;
	if (code < 1 || code > 27) {
		if (fabs(n) < 2e9 && (long)n != code)
			eval_error(e, arg->loc, "tiling number must be between 1 and 27, found %g (%ld: POV-Ray keeps "
			           "it in a byte)", n, code);
		else
			eval_error(e, arg->loc, "tiling number must be between 1 and 27, found %g", n);
		return -1;
	}
	pg->params[0][0] = (double)code;
	return 0;
}

/* POV-Ray keeps pavement's numbers in bytes (the integer part modulo 256). */
static long pavement_byte(double v)
{
	return fabs(v) < 2e9 ? ((long)v & 255) : 0;
}

/* A pavement's numbers, once its modifiers are read: POV-Ray's checks at the
 * end of the pattern (Parse_Pattern), and its reductions: interior and
 * exterior modulo 3, form modulo 4 (four sides) or 3. */
int eval_pavement_check(struct eval *e, scene_pigment *pg, src_loc loc)
{
	static const int most3[] = { 1, 1, 1, 3, 4, 12 }, most4[] = { 1, 1, 2, 5, 12, 35 }, most6[] = { 1, 1, 3, 7, 22 };
	if (pg->kind != PATTERN_PAVEMENT)
		return 0;
	double *p0 = pg->params[0], *p1 = pg->params[1];
	long sides = pavement_byte(p0[0]), tiles = pavement_byte(p0[1]), number = pavement_byte(p0[2]);
	const int *most = sides == 3 ? most3 : sides == 4 ? most4 : sides == 6 ? most6 : NULL;
	long max_tiles = sides == 6 ? 5 : 6;
	int rc = -1;
	if (!most)
		eval_error(e, loc, "number_of_sides of pavement must be 3, 4 or 6, found %g", p0[0]);
	else if (tiles < 1 || tiles > max_tiles)
		eval_error(e, loc, "number_of_tiles of a pavement of %ld sides must be between 1 and %ld, found %g", sides,
		           max_tiles, p0[1]);
	else if (number < 1 || number > most[tiles - 1])
		eval_error(e, loc, "pattern of a pavement of %ld tiles of %ld sides must be between 1 and %d, found %g",
		           tiles, sides, most[tiles - 1], p0[2]);
	else
		rc = 0;
	if (rc) {   /* POV-Ray's defaults, so that nothing later reads a table out of its range */
		sides = 3;
		tiles = number = 1;
	}
	p0[0] = (double)sides;
	p0[1] = (double)tiles;
	p0[2] = (double)number;
	p0[3] = (double)(pavement_byte(p0[3]) % (sides == 4 ? 4 : 3));
	p1[0] = (double)(pavement_byte(p1[0]) % 3);
	p1[1] = (double)(pavement_byte(p1[1]) % 3);
	return rc;
}

/* ---- slope ---- */

const ast_node *eval_slope_word(struct eval *e, const ast_node *item)
{
	const ast_node *w = item;
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && strcmp(item->str, AST_WORD_SLOPE) == 0)
		return item;
	if (item->kind == AST_BINARY && (item->op == '-' || item->op == '+'))
		w = item->kids[0];
	return w->kind == AST_IDENT && strcmp(w->str, AST_WORD_SLOPE) == 0 && !eval_lookup(e, w->str) ? w : NULL;
}

/* Up to two optional floats (a range: low, high), 0 when left out. */
static int slope_range(struct eval *e, struct cursor *c, double range[2])
{
	int err = 0;
	range[0] = range[1] = 0;
	for (int i = 0; i < 2; i++) {
		const ast_node *arg = eval_next_optional(c, &err);
		if (!arg)
			break;
		if (eval_expect_float(e, arg, &range[i]))
			return -1;
	}
	return err ? -1 : 0;
}

/* POV-Ray's low and width of a range; an empty one is none (with its warning). */
static void slope_mod(struct eval *e, src_loc loc, const double range[2], double *low, double *width)
{
	*low = range[0];
	*width = range[1] - range[0];
	if (range[1] != 0 && range[1] == range[0]) {
		eval_warning(e, loc, "zero gradient range, ignored (as POV-Ray does)");
		*low = *width = 0;
	}
}

/* slope { Direction [, Low, High] [altitude Direction [, Low, High]] }: POV-Ray's
 * ParseSlopePattern. The two directions go into params[0].xyz and params[1].xyz
 * as unit vectors times their shares of the sum of their lengths, which is
 * what EvaluateRaw weighs them by; the slope's range in params[0].w (low) and
 * params[1].w (width), the altitude's in altitude. */
static int slope_block(struct eval *e, const ast_node *b, double dir[3], double range[2], double alt[3],
                       double alt_range[2])
{
	struct cursor c;
	int err = 0, rc = 0;
	eval_cursor_init(&c, e, b);
	const ast_node *item = eval_next(&c, &err);
	if (item && item->kind == AST_ARG && item->kw == KW_POINT_AT) {
		eval_warn_once(e, item->loc, "slope point_at", "slope's point_at is not supported yet");
		eval_cursor_free(&c);
		return 2;
	}
	if (!item && !err) {
		eval_error(e, b->loc, "slope needs a direction");
		rc = -1;
	}
	if (item && rc == 0)
		rc = eval_expect_vector(e, item, dir);
	if (rc == 0)
		rc = slope_range(e, &c, range);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		const ast_node *v;
		if (item->kind != AST_IDENT || strcmp(item->str, AST_WORD_ALTITUDE) != 0 || eval_lookup(e, item->str)) {
			rc = eval_not_valid(e, item, "slope");
		} else if ((v = eval_next_expr(&c, &err)) == NULL) {
			eval_error(e, item->loc, "'altitude' needs a vector");
			rc = -1;
		} else if ((rc = eval_expect_vector(e, v, alt)) == 0) {
			rc = slope_range(e, &c, alt_range);
		}
	}
	eval_cursor_free(&c);
	return rc || err ? -1 : 0;
}

int eval_pattern_slope(struct eval *e, struct cursor *c, const ast_node *item, scene_pigment *pg)
{
	double dir[3] = { 0 }, alt[3] = { 0 }, range[2] = { 0 }, alt_range[2] = { 0 };
	int err = 0, rc = 0;
	if (item->kind == AST_BLOCK) {
		rc = slope_block(e, item, dir, range, alt, alt_range);
	} else if (item->kind == AST_BINARY) {   /* slope -V */
		rc = eval_expect_vector(e, item->kids[1], dir);
		for (int k = 0; k < 3 && item->op == '-'; k++)
			dir[k] = -dir[k];
	} else {
		const ast_node *v = eval_next_expr(c, &err);
		if (!v) {
			if (!err)
				eval_error(e, item->loc, "slope needs a direction");
			return -1;
		}
		rc = eval_expect_vector(e, v, dir);
	}
	if (rc)
		return rc;
	double slen = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
	double alen = sqrt(alt[0] * alt[0] + alt[1] * alt[1] + alt[2] * alt[2]);
	if (slen + alen == 0) {
		eval_error(e, item->loc, "slope needs a direction or an altitude of some length");
		return -1;
	}
	double share = slen / (slen + alen);
	for (int k = 0; k < 3; k++) {
		pg->params[0][k] = slen > 0 ? dir[k] / slen * share : 0;
		pg->params[1][k] = alen > 0 ? alt[k] / alen * (1 - share) : 0;
	}
	slope_mod(e, item->loc, range, &pg->params[0][3], &pg->params[1][3]);
	slope_mod(e, item->loc, alt_range, &pg->altitude[0], &pg->altitude[1]);
	return 0;
}

/* ---- image_map ---- */

/* POV-Ray 3.7's file gamma when the scene gives none: PNG's own (its gAMA
 * chunk, else sRGB); sRGB for JPEG, GIF, TGA, BMP and the rest; none for TIFF
 * and PPM (the values are taken as they are); OpenEXR and HDR linear. */
static void image_decode(scene_image *im, const image_data *d)
{
	const char *f = d->format;
	im->decode = SCENE_DECODE_SRGB;
	if (strcmp(f, "png") == 0 && d->encoding == IMAGE_GAMMA_POWER && d->gamma > 0) {
		im->decode = SCENE_DECODE_POWER;
		im->gamma = d->gamma;
	} else if (strcmp(f, "png") == 0 && d->encoding == IMAGE_GAMMA_LINEAR) {
		im->decode = SCENE_DECODE_LINEAR;
	} else if (strcmp(f, "tiff") == 0 || strcmp(f, "pnm") == 0) {
		im->decode = SCENE_DECODE_NONE;
	} else if (strcmp(f, "openexr") == 0 || strcmp(f, "hdr") == 0 || d->encoding == IMAGE_GAMMA_LINEAR) {
		im->decode = SCENE_DECODE_LINEAR;
	}
}

#define IMAGE_MAX_TEXELS (1L << 26)

/* The image at name (looked for as #include looks), with gamma G (0: the
 * file's), read once per path and gamma. -1 after an error at loc. */
/* How an image is read: its colours (image_map); its values as they are
 * (bump_map, image_pattern); its material numbers (material_map). */
enum { USE_COLOUR, USE_DATA, USE_NUMBER };

/* POV-Ray's material numbers: a colormapped PNG's palette indices, any
 * other image's red * 255 (as POV-Ray truncates it), in the red channel. */
static void image_numbers(struct eval *e, const char *path, scene_image *im)
{
	image_limits lim = { IMAGE_MAX_TEXELS, e->opt->mesh_time_limit, eval_memory_left(e) };
	unsigned char *index = NULL;
	int w, h;
	bool indexed = image_indices(path, &lim, &index, &w, &h) && w == im->width && h == im->height;
	long n = (long)im->width * im->height;
	for (long i = 0; i < n; i++) {
		float *c = &im->rgba[4 * i];
		c[0] = indexed ? index[i] : (float)(int)((double)c[0] * 255.0 + 1e-4);   /* 1e-4: 8 bits exactly */
		c[1] = c[2] = 0;
		c[3] = 1;
	}
	free(index);
	im->premultiplied = false;
}

/* An image_map's filter and transmit: [0] filter, [1] transmit, for all
 * entries (filter all F) or for one (filter N, F). POV-Ray sets them in an
 * indexed image's palette, replacing what the entries had; in another image
 * the values for all are added to each texel's. */
struct palette_ft {
	bool any;                 /* some value written for one entry */
	bool all[2], set[2][256];
	float all_value[2], value[2][256];
	src_loc loc;              /* the first for one entry */
};

/* POV-Ray's palette, filter and transmit set, on texel's indices: the alpha
 * becomes 1 - transmit and the filters a plane of their own (when some is
 * not 0). */
static int palette_apply(struct eval *e, scene_image *im, const unsigned char *index, const struct palette_ft *ft)
{
	long n = (long)im->width * im->height;
	bool filters = false;
	for (int i = 0; i < 256; i++)
		filters |= (ft->set[0][i] && ft->value[0][i] != 0) || (ft->all[0] && ft->all_value[0] != 0);
	if (filters) {   /* a float here, a float4 on the device */
		if (eval_memory_claim(e, im->loc, (double)n * 5 * sizeof(float), "the image's filters"))
			return -1;
		im->filter = eval_xrealloc(NULL, (size_t)n * sizeof *im->filter);
	}
	for (long k = 0; k < n; k++) {
		int i = index[k];
		float *c = &im->rgba[4 * k];
		if (ft->set[1][i] || ft->all[1])
			c[3] = 1 - (ft->set[1][i] ? ft->value[1][i] : ft->all_value[1]);
		if (filters)
			im->filter[k] = ft->set[0][i] ? ft->value[0][i] : ft->all[0] ? ft->all_value[0] : 0;
	}
	return 0;
}

/* The image for a pattern; an image_map's with its palette_ft (NULL for
 * none), which *palette says it took (the image has a palette). */
static int image_load(struct eval *e, const char *name, double gamma, int premul, int how, src_loc loc,
                      const struct palette_ft *ft, bool *palette)
{
	scene *s = e->s;
	char *path = eval_find_file(e, loc.file, name);
	const char *use = path ? path : name;
	char key[4200];
	unsigned hash = 2166136261u;   /* FNV-1a of the palette's filter and transmit, which make a variant */
	bool ft_any = ft && (ft->any || ft->all[0] || ft->all[1]);
	for (size_t i = 0; ft_any && i < offsetof(struct palette_ft, loc); i++)
		hash = (hash ^ ((const unsigned char *)ft)[i]) * 16777619u;
	/* POV-Ray 3.7 in a scene older than 3.7 (its gamma modes None and
	 * AssumedGamma36) decodes an image's colours with the working gamma: it
	 * takes them as they are, unless the image gives its own gamma. */
	bool as_they_are = how == USE_COLOUR && gamma <= 0 && e->version_given && e->version < 3.7;
	snprintf(key, sizeof key, "%s\t%g\t%d%s%s%08x%s", use, gamma, premul,
	         how == USE_DATA ? "\tdata" : how == USE_NUMBER ? "\tnumber" : "", ft_any ? "\tft" : "",
	         ft_any ? hash : 0u, as_they_are ? "\tlegacy" : "");
	*palette = false;
	for (int i = 0; i < s->n_images; i++)
		if (strcmp(s->images[i].key, key) == 0) {
			free(path);
			*palette = s->images[i].palette;
			return i;
		}
	image_data d;
	char why[512];
	if (eval_access(e, use, false, loc, how == USE_COLOUR ? "an image_map" : how == USE_DATA ? "a bump_map or image_pattern"
	                                                                           : "a material_map")) {
		free(path);
		return -1;
	}
	image_limits lim = { IMAGE_MAX_TEXELS, e->opt->mesh_time_limit, eval_memory_left(e) };
	if (image_read(use, &lim, &d, why, sizeof why)) {
		eval_error(e, loc, "cannot read image '%s': %s", name, why);
		free(path);
		return -1;
	}
	eval_memory_claim(e, loc, (double)d.width * d.height * 4 * sizeof *d.rgba, "the image");   /* fits: checked */
	scene_image im = { .key = eval_xstrdup(key), .rgba = d.rgba, .width = d.width, .height = d.height,
	                   .premultiplied = premul >= 0 ? premul != 0 : d.premultiplied != 0, .loc = loc };
	image_decode(&im, &d);
	im.data = how != USE_COLOUR;
	if (im.data || as_they_are)   /* POV-Ray reads a bump_map's, image_pattern's or material_map's values as they are */
		im.decode = SCENE_DECODE_NONE;
	if (how == USE_NUMBER)
		image_numbers(e, use, &im);
	if (ft_any) {
		unsigned char *index = NULL;
		int w, h;
		bool indexed = image_indices(use, &lim, &index, &w, &h) && w == im.width && h == im.height;
		int bad = indexed ? palette_apply(e, &im, index, ft) : 0;
		free(index);
		if (!indexed && ft->any)   /* POV-Ray: "filter not allowed with non color-mapped image" */
			eval_error(e, ft->loc, "filter and transmit of one palette entry need an image with a palette "
			           "(a colormapped PNG or a GIF), which '%s' is not", name);
		if (bad || (!indexed && ft->any)) {
			free(path);
			free(im.filter);
			free(im.key);
			free(im.rgba);
			return -1;
		}
		*palette = im.palette = indexed;
	}
	free(path);
	if (gamma > 0 && how != USE_NUMBER) {
		im.decode = SCENE_DECODE_POWER;
		im.gamma = (float)gamma;
		im.gamma_given = true;
	}
	double sum[4] = { 0 };
	long n = (long)d.width * d.height;
	for (long i = 0; i < n; i++)
		for (int k = 0; k < 4; k++)
			sum[k] += d.rgba[4 * i + k];
	for (int k = 0; k < 4; k++)
		im.average[k] = (float)(sum[k] / n);
	return scene_add_image(s, &im);
}

/* What an image_map's item is waiting for. */
enum { IM_ANY, IM_FILE, IM_MAP_TYPE, IM_INTERPOLATE, IM_GAMMA, IM_PREMUL, IM_FT, IM_FT_VALUE, IM_BUMP_SIZE };

struct image_map_read {
	int want;                 /* IM_ */
	int ft;                   /* KW_FILTER or KW_TRANSMIT being read */
	bool ft_all;
	int ft_index;             /* the palette entry being given it, when not all */
	struct palette_ft palette;
	char *file;
	src_loc file_loc;
	double gamma;             /* 0: the file's */
	int premul;               /* -1: the file's */
	bool alpha;               /* use_alpha (image_pattern) */
	scene_pigment *pg;        /* kind: PATTERN_IMAGE_MAP, _IMAGE_PATTERN, _BUMP_MAP or _MATERIAL_MAP */
	int (*other)(struct eval *, const ast_node *, void *);   /* material_map's textures */
	void *ctx;
};

static int image_map_item(struct eval *e, const ast_node *n, struct image_map_read *r);

/* filter and transmit are colour components to the parser: "0.3 transmit all"
 * comes as one node. Its parts are read in the order they were written. */
static int image_map_component(struct eval *e, const ast_node *n, struct image_map_read *r)
{
	if (n->n_kids == 2 && image_map_item(e, n->kids[0], r))
		return -1;
	if (r->want != IM_ANY) {
		eval_error(e, n->loc, "expected a value before '%s'", ast_keyword_name(n->kw));
		return -1;
	}
	r->want = IM_FT;
	r->ft = n->kw;
	return image_map_item(e, n->kids[n->n_kids - 1], r);
}

static int image_map_item(struct eval *e, const ast_node *n, struct image_map_read *r)
{
	if (n->kind == AST_COLOR && (n->kw == KW_FILTER || n->kw == KW_TRANSMIT) && r->pg->kind == PATTERN_IMAGE_MAP)
		return image_map_component(e, n, r);
	const char *name = word(e, n);
	double v;
	switch (r->want) {
	case IM_FILE:
	case IM_ANY:
		if (r->want == IM_ANY && r->file && name) {
			static const char *const words[] = { AST_WORD_MAP_TYPE, AST_WORD_INTERPOLATE, AST_WORD_GAMMA,
			                                     AST_WORD_PREMULTIPLIED };
			static const int wants[] = { IM_MAP_TYPE, IM_INTERPOLATE, IM_GAMMA, IM_PREMUL };
			for (int i = 0; i < 4; i++)
				if (strcmp(name, words[i]) == 0) {
					r->want = wants[i];
					return 0;
				}
			if (strcmp(name, AST_WORD_USE_COLOR) == 0 || strcmp(name, AST_WORD_USE_COLOUR) == 0) {
				r->alpha = false;
				return 0;
			}
			if (strcmp(name, AST_WORD_USE_INDEX) == 0) {   /* eclat keeps no palette indices */
				if (r->pg->kind != PATTERN_IMAGE_MAP)
					eval_warn_once(e, n->loc, "use_index", "use_index: eclat keeps no palette "
					               "indices; the colours' grey is used");
				r->alpha = false;
				return 0;
			}
			if (strcmp(name, AST_WORD_USE_ALPHA) == 0 && r->pg->kind == PATTERN_IMAGE_PATTERN) {
				r->alpha = true;
				return 0;
			}
			if (strcmp(name, AST_WORD_BUMP_SIZE) == 0 && r->pg->kind == PATTERN_BUMP_MAP) {
				r->want = IM_BUMP_SIZE;
				return 0;
			}
		}
		if (r->want == IM_ANY && n->kind == AST_FLAG && n->kw == KW_ONCE && r->file) {
			r->pg->params[0][3] = 1;
			return 0;
		}
		if (!r->file && name) {
			static const char *const formats[] = { "png", "jpeg", "tiff", "exr", "hdr", "gif", "tga", "ppm",
			                                       "pgm", "bmp", "iff", "sys" };
			for (size_t i = 0; i < sizeof formats / sizeof *formats; i++)
				if (strcmp(name, formats[i]) == 0 && r->want == IM_ANY) {
					r->want = IM_FILE;
					return 0;
				}
		}
		if (!r->file) {
			r->want = IM_ANY;
			r->file_loc = n->loc;
			return eval_expect_string(e, n, &r->file);
		}
		if (r->other && r->want == IM_ANY) {
			int rc = r->other(e, n, r->ctx);
			if (rc <= 0)
				return rc;
		}
		return eval_not_valid(e, n, r->pg->kind == PATTERN_MATERIAL_MAP ? "a material_map" : r->pg->kind == PATTERN_BUMP_MAP ? "a bump_map"
		                          : r->pg->kind == PATTERN_IMAGE_PATTERN ? "an image_pattern" : "an image_map");
	case IM_BUMP_SIZE:
		if (eval_expect_float(e, n, &r->pg->bump_size))
			return -1;
		break;
	case IM_MAP_TYPE:
		if (eval_expect_float(e, n, &v))
			return -1;
		if (v != 0 && v != 1 && v != 2 && v != 5) {
			eval_error(e, n->loc, "map_type is 0 (planar), 1 (spherical), 2 (cylindrical) or 5 (torus)");
			return -1;
		}
		r->pg->params[0][1] = v;
		break;
	case IM_INTERPOLATE:
		if (eval_expect_float(e, n, &v))
			return -1;
		int k = eval_int_of(v);
		if (k != 2 && k != 3 && k != 4) {
			eval_error(e, n->loc, "interpolate is 2 (bilinear), 3 (bicubic) or 4 (normalized distance)");
			return -1;
		}
		r->pg->params[0][2] = k;
		break;
	case IM_GAMMA:
		if (eval_expect_float(e, n, &r->gamma))
			return -1;
		if (r->gamma <= 0) {
			eval_error(e, n->loc, "gamma value must be positive");
			return -1;
		}
		break;
	case IM_PREMUL:
		if (eval_expect_float(e, n, &v))
			return -1;
		r->premul = eval_int_of(v) != 0;
		break;
	case IM_FT:
		if (name && strcmp(name, AST_WORD_ALL) == 0) {
			r->ft_all = true;
			r->want = IM_FT_VALUE;
			return 0;
		}
		if (eval_expect_float(e, n, &v))
			return -1;
		r->ft_index = (int)(v + 0.01);   /* POV-Ray's rounding of the entry */
		if (!(v + 0.01 >= 0 && v + 0.01 < 256)) {
			eval_error(e, n->loc, "%s's palette entry must be from 0 to 255, not %g", ast_keyword_name(r->ft), v);
			return -1;
		}
		if (!r->palette.any)
			r->palette.loc = n->loc;
		r->palette.any = true;
		r->ft_all = false;
		r->want = IM_FT_VALUE;
		return 0;
	case IM_FT_VALUE: {
		if (eval_expect_float(e, n, &v))
			return -1;
		int k = r->ft == KW_FILTER ? 0 : 1;
		if (r->ft_all) {
			r->pg->params[1][k] = v;
			r->palette.all[k] = true;
			r->palette.all_value[k] = (float)v;
		} else {
			r->palette.set[k][r->ft_index] = true;
			r->palette.value[k][r->ft_index] = (float)v;
		}
		break;
	}
	}
	r->want = IM_ANY;
	return 0;
}

/* An image's block into pg, whose kind says which: image_map { [FORMAT]
 * "File" [gamma G] [premultiplied B] [map_type N] [interpolate N] [once]
 * [filter all F] [transmit all T] }, image_pattern { ... [use_alpha] },
 * bump_map { ... [bump_size B] } (and use_color, use_index). An image_map's
 * pg gets a one-entry map of its average colour. */
static int image_block(struct eval *e, const ast_node *b, scene_pigment *pg,
                       int (*other)(struct eval *, const ast_node *, void *), void *ctx)
{
	struct image_map_read r = { .premul = -1, .pg = pg, .other = other, .ctx = ctx };
	const char *what = pg->kind == PATTERN_BUMP_MAP ? "bump_map" : pg->kind == PATTERN_IMAGE_PATTERN ? "image_pattern"
	                 : pg->kind == PATTERN_MATERIAL_MAP ? "material_map" : "image_map";
	pg->params[0][0] = -1;
	struct cursor c;
	int err = 0, rc = 0;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL)
		rc = image_map_item(e, item, &r);
	eval_cursor_free(&c);
	if (!rc && !err && r.want != IM_ANY) {
		eval_error(e, b->loc, "the %s ends before a value it needs", what);
		rc = -1;
	}
	if (!rc && !err && !r.file) {
		eval_error(e, b->loc, "%s %s needs a file name", what[1] == 'm' ? "an" : "a", what);
		rc = -1;
	}
	int how = pg->kind == PATTERN_IMAGE_MAP ? USE_COLOUR : pg->kind == PATTERN_MATERIAL_MAP ? USE_NUMBER : USE_DATA;
	bool palette = false;
	int at = rc || err ? -1 : image_load(e, r.file, r.gamma, r.premul, how, r.file_loc,
	                                     how == USE_COLOUR ? &r.palette : NULL, &palette);
	free(r.file);
	if (at < 0)
		return -1;
	pg->params[0][0] = at;
	const scene_image *im = &e->s->images[at];
	if (palette)   /* the palette holds them now, set rather than added */
		pg->params[1][0] = pg->params[1][1] = 0;
	if (pg->kind != PATTERN_IMAGE_MAP) {
		pg->frequency = 0;   /* POV-Ray's: its value is the image's */
		pg->params[1][0] = r.alpha;
		pg->params[1][1] = im->average[3] < 1;   /* some alpha: use_alpha reads it, else red */
		return 0;
	}
	pg->map = eval_xrealloc(pg->map, sizeof *pg->map);
	double filter = 0;
	long n = (long)im->width * im->height;
	for (long i = 0; im->filter && i < n; i++)
		filter += im->filter[i] / n;
	pg->map[0] = (scene_map_entry){ .colour = { im->average[0], im->average[1], im->average[2],
	                                            (float)(pg->params[1][0] + filter),
	                                            1 - im->average[3] + (float)pg->params[1][1] },
	                                .pigment = -1 };
	pg->n_map = 1;
	return 0;
}

int eval_image_map(struct eval *e, const ast_node *b, scene_pigment *pg)
{
	return image_block(e, b, pg, NULL, NULL);
}

/* image_pattern { ... } in a pigment, texture or normal: pg's pattern, whose
 * map comes later. */
int eval_image_pattern(struct eval *e, const ast_node *b, scene_pigment *pg)
{
	pg->kind = PATTERN_IMAGE_PATTERN;
	return image_block(e, b, pg, NULL, NULL);
}

/* bump_map { ... } in a normal; its bump_size, if any, is pg's amount. */
int eval_bump_map(struct eval *e, const ast_node *b, scene_pigment *pg)
{
	pg->kind = PATTERN_BUMP_MAP;
	return image_block(e, b, pg, NULL, NULL);
}

int eval_material_map(struct eval *e, const ast_node *b, scene_pigment *pg,
                      int (*texture)(struct eval *, const ast_node *, void *), void *ctx)
{
	pg->kind = PATTERN_MATERIAL_MAP;
	return image_block(e, b, pg, texture, ctx);
}
