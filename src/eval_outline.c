/* eval_outline.c: the arguments of polygon, prism and text, which are not
 * positional (a count and then that many points, spline keywords, a font and a
 * string), read into an outline of edges in the scene (src/prism.h):
 *
 *   polygon { Number, <Point>... }
 *   prism { [linear_sweep | conic_sweep] [linear_spline | quadratic_spline |
 *           cubic_spline | bezier_spline] Height1, Height2, Number, <Point>... }
 *   text { ttf "Font" | internal N  "String" Thickness, <Offset> }
 *
 * Curves (a prism's splines, a font's quadratic and cubic pieces) are
 * flattened here into edges, finely enough that no edge is further than
 * FLAT_TOLERANCE of the shape's size from the curve (POV-Ray solves them
 * exactly). Glyphs are read with FreeType. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include "eval_int.h"
#include "loader.h"
#include "prism.h"
#include "revolve.h"
#include "vec3.h"

#define POV_EPSILON 1e-10          /* POV-Ray's EPSILON: points this close are one */
#define FLAT_TOLERANCE 1e-3        /* of the shape's size (a prism) or the em (text) */
#define FLAT_MAX 64                /* edges per curve piece, at most */

/* ---- building an outline ---- */

struct build {
	scene_outline ol;
	int cap, cap_glyphs;
};

static void add_edge(struct build *b, const double p[2], const double q[2])
{
	if (p[0] == q[0] && p[1] == q[1])
		return;
	if (b->ol.n_edges == b->cap) {
		b->cap = b->cap ? 2 * b->cap : 64;
		b->ol.edge = eval_xrealloc(b->ol.edge, b->cap * sizeof *b->ol.edge);
	}
	double *e = b->ol.edge[b->ol.n_edges++];
	e[0] = p[0];
	e[1] = p[1];
	e[2] = q[0];
	e[3] = q[1];
}

static void start_glyph(struct build *b)
{
	if (b->ol.n_glyphs + 2 > b->cap_glyphs) {
		b->cap_glyphs = b->cap_glyphs ? 2 * b->cap_glyphs : 16;
		b->ol.glyph = eval_xrealloc(b->ol.glyph, b->cap_glyphs * sizeof *b->ol.glyph);
	}
	b->ol.glyph[b->ol.n_glyphs++] = b->ol.n_edges;
}

/* The cubic ((a t + b) t + c) t + d for t in [0, 1] as edges, as many as keep
 * it within tol: a chord strays at most h^2 / 8 times the second derivative. */
static void add_cubic(struct build *b, const double a[2], const double bb[2], const double c[2], const double d[2],
                      double tol)
{
	double second = 6 * hypot(a[0], a[1]) + 2 * hypot(bb[0], bb[1]);
	int n = second > 0 && tol > 0 ? (int)ceil(sqrt(second / (8 * tol))) : 1;
	n = n < 1 ? 1 : n > FLAT_MAX ? FLAT_MAX : n;
	double p[2] = { d[0], d[1] };
	for (int i = 1; i <= n; i++) {
		double t = (double)i / n, q[2];
		for (int k = 0; k < 2; k++)
			q[k] = ((a[k] * t + bb[k]) * t + c[k]) * t + d[k];
		add_edge(b, p, q);
		memcpy(p, q, sizeof p);
	}
}

/* Stores the outline in the scene, its edges turned (prism_orient). */
static void store(struct eval *e, struct build *b, scene_object *o)
{
	prism_orient(&b->ol);
	o->outline = scene_add_outline(e->s, &b->ol);
}

/* ---- the items ---- */

static int next_float(struct eval *e, struct cursor *c, const ast_node *blk, const char *what, double *f)
{
	int err = 0;
	const ast_node *arg = eval_next_expr(c, &err);
	if (!arg) {
		if (!err) {
			const ast_node *next = eval_next(c, &err);
			eval_error(e, next ? next->loc : blk->loc, "%s needs %s", blk->kw == KW_UNKNOWN ? blk->str : "it",
			           what);
		}
		return -1;
	}
	return eval_expect_float(e, arg, f);
}

/* A point of n components (2: a prism's, a float making both). */
static int next_point(struct eval *e, struct cursor *c, const ast_node *blk, int i, int count, int n,
                      double out[3])
{
	int err = 0;
	const ast_node *arg = eval_next_expr(c, &err);
	if (!arg) {
		if (!err) {
			const ast_node *next = eval_next(c, &err);
			eval_error(e, next ? next->loc : blk->loc, "%s has %d points of the %d its count says", blk->str, i,
			           count);
		}
		return -1;
	}
	value v;
	if (eval_expr(e, arg, &v))
		return -1;
	if (!eval_is_numeric(v.kind) || v.kind == V_COLOR) {
		eval_error(e, arg->loc, "%s's point %d: expected a vector, found %s", blk->str, i + 1, eval_kind_name(v.kind));
		eval_value_free(&v);
		return -1;
	}
	double w[5];
	eval_widen(&v, n, w);
	eval_value_free(&v);
	for (int k = 0; k < 3; k++)
		out[k] = k < n ? w[k] : 0;
	for (int k = 0; k < n; k++)
		if (!isfinite(out[k])) {
			eval_error(e, arg->loc, "%s's point %d is not a number", blk->str, i + 1);
			return -1;
		}
	return 0;
}

static int count_arg(struct eval *e, struct cursor *c, const ast_node *b, int *n)
{
	double f;
	if (next_float(e, c, b, "a count of points", &f))
		return -1;
	if (!(f >= 0 && f < 1e7)) {
		eval_error(e, b->loc, "%s: a count of %g points", b->str, f);
		return -1;
	}
	*n = (int)f;
	return 0;
}

static bool same2(const double *a, const double *b)
{
	return fabs(a[0] - b[0]) < POV_EPSILON && fabs(a[1] - b[1]) < POV_EPSILON;
}

/* ---- polygon ---- */

/* POV-Ray's plane of a polygon: the first point, the first edge of a length
 * and the first point off its line; false when the points are on one line. */
static bool polygon_frame(double (*pt)[3], int n, scene_object *o)
{
	double u[3], v[3], w[3];
	int i;
	for (i = 1; i < n; i++) {
		for (int k = 0; k < 3; k++)
			u[k] = pt[i][k] - pt[0][k];
		if (vec3_dot(u, u) > POV_EPSILON)
			break;
	}
	for (i++; i < n; i++) {
		for (int k = 0; k < 3; k++)
			v[k] = pt[i][k] - pt[0][k];
		vec3_cross(u, v, w);
		if (vec3_dot(v, v) > POV_EPSILON && vec3_dot(w, w) > POV_EPSILON)
			break;
	}
	if (i >= n)
		return false;
	vec3_cross(v, w, u);
	vec3_cross(w, u, v);
	vec3_normalize(u);
	vec3_normalize(v);
	vec3_normalize(w);
	/* prism space: x along u, y along the normal w, z along v */
	memcpy(o->p[0], pt[0], sizeof o->p[0]);
	memcpy(o->n[0], u, sizeof u);
	memcpy(o->n[1], w, sizeof w);
	memcpy(o->n[2], v, sizeof v);
	return true;
}

/* The edges of points that close their subpolygons by repeating their first
 * (POV-Ray's in_polygon walk: the step from one subpolygon to the next is no edge). */
static void closed_edges(struct build *b, double (*pt)[2], int n)
{
	int first = 0, i0 = 0;
	for (int i = 1; i < n;) {
		add_edge(b, pt[i0], pt[i]);
		if (i < n - 2 && pt[i][0] == pt[first][0] && pt[i][1] == pt[first][1]) {
			first = i0 = i + 1;
			i += 2;
		} else {
			i0 = i++;
		}
	}
}

/* Snaps the points that close a polygon's subpolygons onto their first, as
 * POV-Ray does; false when the last is not closed, *last then the first point
 * of the last subpolygon. */
static bool close_points(double (*pt)[3], int n, int *last)
{
	bool closed = false;
	int p = 0;
	for (int i = 1; i < n; i++) {
		closed = fabs(pt[p][0] - pt[i][0]) < POV_EPSILON && fabs(pt[p][1] - pt[i][1]) < POV_EPSILON &&
		         fabs(pt[p][2] - pt[i][2]) < POV_EPSILON;
		if (!closed)
			continue;
		memcpy(pt[i], pt[p], sizeof pt[i]);
		if (++i < n)
			p = i;
	}
	*last = p;
	return closed;
}

static int polygon_args(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	int n;
	if (count_arg(e, c, b, &n))
		return -1;
	if (n < 3) {
		eval_error(e, b->loc, "a polygon needs at least three points, not %d", n);
		return -1;
	}
	double (*pt)[3] = eval_xrealloc(NULL, (n + 1) * sizeof *pt);
	for (int i = 0; i < n; i++)
		if (next_point(e, c, b, i, n, 3, pt[i])) {
			free(pt);
			return -1;
		}
	int last;
	if (!close_points(pt, n, &last)) {
		eval_warning(e, b->loc, "polygon not closed; closing it (as POV-Ray does)");
		memcpy(pt[n++], pt[last], sizeof pt[0]);
	}
	struct build bld = { 0 };
	if (!polygon_frame(pt, n, o)) {
		eval_warning(e, b->loc, "the points of a polygon are on one line; it is left out, as POV-Ray does");
	} else {
		double (*flat)[2] = eval_xrealloc(NULL, n * sizeof *flat);
		bool planar = true;
		for (int i = 0; i < n; i++) {
			double d[3] = { pt[i][0] - o->p[0][0], pt[i][1] - o->p[0][1], pt[i][2] - o->p[0][2] };
			flat[i][0] = vec3_dot(d, o->n[0]);
			flat[i][1] = vec3_dot(d, o->n[2]);
			planar = planar && fabs(vec3_dot(d, o->n[1])) <= 1e-6 * (1 + sqrt(vec3_dot(d, d)));
		}
		if (planar)
			closed_edges(&bld, flat, n);
		else
			eval_warning(e, b->loc, "the points of a polygon are not in one plane; it is left out, as POV-Ray does");
		free(flat);
	}
	free(pt);
	store(e, &bld, o);
	return 0;
}

/* ---- prism ---- */

enum { LINEAR, QUADRATIC, CUBIC, BEZIER };

/* The keywords before the heights; 1 when item is none of them. */
static int prism_keyword(struct eval *e, const ast_node *item, int *spline, bool *conic)
{
	static const char *const splines[] = { "linear_spline", "quadratic_spline", "cubic_spline", "bezier_spline" };
	if (item->kind != AST_IDENT || eval_lookup(e, item->str))
		return 1;
	for (int i = 0; i < 4; i++)
		if (strcmp(item->str, splines[i]) == 0) {
			*spline = i;
			return 0;
		}
	if (strcmp(item->str, AST_WORD_LINEAR_SWEEP) == 0 || strcmp(item->str, AST_WORD_CONIC_SWEEP) == 0) {
		*conic = item->str[0] == 'c';
		return 0;
	}
	return 1;
}

/* Segment i's cubic (POV-Ray's Compute_Prism): coefficients a, b, c, d. */
static void spline_piece(int kind, double (*P)[2], int i, double cf[4][2])
{
	static const double m[4][4][4] = {
		[LINEAR] = { { 0, 0, 0, 0 }, { 0, 0, 0, 0 }, { -1, 1, 0, 0 }, { 1, 0, 0, 0 } },
		[QUADRATIC] = { { 0, 0, 0, 0 }, { 0.5, -1, 0.5, 0 }, { -0.5, 0, 0.5, 0 }, { 0, 1, 0, 0 } },
		[CUBIC] = { { -0.5, 1.5, -1.5, 0.5 }, { 1, -2.5, 2, -0.5 }, { -0.5, 0, 0.5, 0 }, { 0, 1, 0, 0 } },
		[BEZIER] = { { -1, 3, -3, 1 }, { 3, -6, 3, 0 }, { -3, 3, 0, 0 }, { 1, 0, 0, 0 } },
	};
	int used = kind == LINEAR ? 2 : kind == QUADRATIC ? 3 : 4;
	for (int r = 0; r < 4; r++)
		for (int k = 0; k < 2; k++) {
			cf[r][k] = 0;
			for (int j = 0; j < used; j++)
				cf[r][k] += m[kind][r][j] * P[i + j][k];
		}
}

/* POV-Ray's walk over a prism's points (Compute_Prism): the pieces and the
 * steps between subpolygons; -1 when the points run out. */
static int prism_edges(struct build *b, int kind, double (*P)[2], int n, double tol)
{
	static const int need[] = { 1, 2, 3, 3 };
	double first[2];
	memcpy(first, P[kind == LINEAR ? 0 : 1], sizeof first);
	for (int i = 0; i < n - 1; i++) {
		if (i + need[kind] >= n)
			return -1;
		double cf[4][2];
		spline_piece(kind, P, i, cf);
		add_cubic(b, cf[0], cf[1], cf[2], cf[3], kind == LINEAR ? 0 : tol);
		switch (kind) {
		case LINEAR:
			if (same2(P[i + 1], first) && ++i + 1 < n)
				memcpy(first, P[i + 1], sizeof first);
			break;
		case QUADRATIC:
		case CUBIC:
			if (same2(P[i + 2], first)) {
				i += kind == QUADRATIC ? 2 : 3;
				if (i + 2 < n)
					memcpy(first, P[i + 2], sizeof first);
			}
			break;
		default:
			i += 3;
		}
	}
	return 0;
}

/* Whether a prism's points close their subpolygons (POV-Ray's Parse_Prism);
 * a linear one's closing points are snapped onto their first. *last: the
 * first point of the last subpolygon, which closes an open linear prism. */
static bool prism_closed(int kind, double (*P)[2], int n, int *last)
{
	bool closed = false;
	if (kind == BEZIER) {
		int loop = 0;
		for (int i = 4; i < n; i += 4)
			if (!same2(P[i], P[i - 1])) {
				if (!same2(P[i - 1], P[loop]))
					return false;
				loop = i;
			}
		return same2(P[n - 1], P[loop]);
	}
	int i = kind == LINEAR ? 1 : 2, p = i - 1;
	*last = p;
	for (; i < n; i++) {
		closed = same2(P[p], P[i]);
		if (!closed)
			continue;
		i += kind == LINEAR ? 1 : kind == QUADRATIC ? 2 : 3;
		if (i < n)
			p = *last = i;
	}
	return closed;
}

/* "linear_spline -1, 1, ..." parses as the difference linear_spline - 1, the
 * keyword being an identifier: such a sum's leftmost term, or NULL. */
static const ast_node *leading_word(const ast_node *n)
{
	while (n->kind == AST_BINARY && (n->op == '+' || n->op == '-'))
		n = n->kids[0];
	return n->kind == AST_IDENT ? n : NULL;
}

/* The value such a sum gives without its keyword. */
static int value_after_word(struct eval *e, const ast_node *n, double *f)
{
	double r;
	if (n->kind == AST_IDENT) {
		*f = 0;
		return 0;
	}
	if (value_after_word(e, n->kids[0], f) || eval_expect_float(e, n->kids[1], &r))
		return -1;
	*f = n->op == '+' ? *f + r : *f - r;
	return 0;
}

static int prism_args(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	int spline = LINEAR, err = 0, n;
	bool conic = false, have_h1 = false;
	const ast_node *item, *w;
	double h1, h2;
	while ((item = eval_next(c, &err)) != NULL) {
		if (prism_keyword(e, item, &spline, &conic) == 0)
			continue;
		if (AST_IS_EXPRESSION(item->kind) && item->kind == AST_BINARY && (w = leading_word(item)) &&
		    prism_keyword(e, w, &spline, &conic) == 0) {
			if (value_after_word(e, item, &h1))
				return -1;
			have_h1 = true;
			item = NULL;
		}
		break;
	}
	if (err)
		return -1;
	if (item)
		eval_unget(c, item);
	if ((!have_h1 && next_float(e, c, b, "two heights, a count and its points", &h1)) ||
	    next_float(e, c, b, "two heights, a count and its points", &h2) || count_arg(e, c, b, &n))
		return -1;
	o->radius = fmin(h1, h2);
	o->param[0] = fmax(h1, h2);
	o->param[1] = conic;
	static const char *const too_few[] = {
		"a prism with linear_spline needs at least three points",
		"a prism with quadratic_spline needs at least five points",
		"a prism with cubic_spline needs at least six points",
		"a prism with bezier_spline needs four points per segment",
	};
	static const int least[] = { 3, 5, 6, 4 };
	if (n < least[spline] || (spline == BEZIER && n % 4 != 0)) {
		eval_error(e, b->loc, "%s, not %d", too_few[spline], n);
		return -1;
	}
	double (*P)[2] = eval_xrealloc(NULL, (n + 1) * sizeof *P);
	for (int i = 0; i < n; i++) {
		double p[3];
		if (next_point(e, c, b, i, n, 2, p)) {
			free(P);
			return -1;
		}
		memcpy(P[i], p, sizeof P[i]);
	}
	int last = 0;
	bool closed = prism_closed(spline, P, n, &last);
	struct build bld = { 0 };
	if (!closed && spline == LINEAR) {
		eval_warning(e, b->loc, "linear prism not closed; closing it (as POV-Ray does)");
		memcpy(P[n++], P[last], sizeof P[0]);
	}
	if (!closed && spline != LINEAR) {
		eval_warning(e, b->loc, "prism not closed; it is left out, as POV-Ray does");
	} else {
		double lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY, -INFINITY };
		for (int i = 0; i < n; i++)
			for (int k = 0; k < 2; k++) {
				lo[k] = fmin(lo[k], P[i][k]);
				hi[k] = fmax(hi[k], P[i][k]);
			}
		double size = fmax(hi[0] - lo[0], hi[1] - lo[1]);
		if (prism_edges(&bld, spline, P, n, FLAT_TOLERANCE * size)) {
			eval_error(e, b->loc, "too few points in a prism (a subpolygon not closed? control points missing?)");
			free(P);
			free(bld.ol.edge);
			return -1;
		}
	}
	free(P);
	store(e, &bld, o);
	return 0;
}

/* ---- text ---- */

struct glyph_walk {
	struct build *b;
	double scale, x, y;     /* font units to the em; where the glyph's origin is */
	double cur[2], start[2];
	bool open;
};

static void font_point(const struct glyph_walk *w, const FT_Vector *v, double out[2])
{
	out[0] = v->x * w->scale + w->x;
	out[1] = v->y * w->scale + w->y;
}

static void close_contour(struct glyph_walk *w)
{
	if (w->open)
		add_edge(w->b, w->cur, w->start);
	w->open = false;
}

static int move_to(const FT_Vector *to, void *user)
{
	struct glyph_walk *w = user;
	close_contour(w);
	font_point(w, to, w->start);
	memcpy(w->cur, w->start, sizeof w->cur);
	w->open = true;
	return 0;
}

static int line_to(const FT_Vector *to, void *user)
{
	struct glyph_walk *w = user;
	double q[2];
	font_point(w, to, q);
	add_edge(w->b, w->cur, q);
	memcpy(w->cur, q, sizeof q);
	return 0;
}

static int conic_to(const FT_Vector *control, const FT_Vector *to, void *user)
{
	struct glyph_walk *w = user;
	double p1[2], p2[2], a[2] = { 0, 0 }, b[2], c[2];
	font_point(w, control, p1);
	font_point(w, to, p2);
	for (int k = 0; k < 2; k++) {
		b[k] = w->cur[k] - 2 * p1[k] + p2[k];
		c[k] = 2 * (p1[k] - w->cur[k]);
	}
	add_cubic(w->b, a, b, c, w->cur, FLAT_TOLERANCE);
	memcpy(w->cur, p2, sizeof p2);
	return 0;
}

static int cubic_to(const FT_Vector *c1, const FT_Vector *c2, const FT_Vector *to, void *user)
{
	struct glyph_walk *w = user;
	double p1[2], p2[2], p3[2], a[2], b[2], c[2];
	font_point(w, c1, p1);
	font_point(w, c2, p2);
	font_point(w, to, p3);
	for (int k = 0; k < 2; k++) {
		a[k] = p3[k] - 3 * p2[k] + 3 * p1[k] - w->cur[k];
		b[k] = 3 * p2[k] - 6 * p1[k] + 3 * w->cur[k];
		c[k] = 3 * p1[k] - 3 * w->cur[k];
	}
	add_cubic(w->b, a, b, c, w->cur, FLAT_TOLERANCE);
	memcpy(w->cur, p3, sizeof p3);
	return 0;
}

/* POV-Ray's fonts for internal N. */
static const char *internal_font(int n)
{
	return n == 1 ? "timrom.ttf" : n == 2 ? "cyrvetic.ttf" : n == 3 ? "crystal.ttf" : "povlogo.ttf";
}

/* The next character of a UTF-8 string (a byte that is no UTF-8 is itself). */
static unsigned next_char(const unsigned char **s)
{
	const unsigned char *p = *s;
	unsigned c = *p;
	int extra = c >= 0xf0 && c < 0xf8 ? 3 : c >= 0xe0 ? 2 : c >= 0xc0 ? 1 : 0;
	if (c < 0x80)
		extra = 0;
	for (int i = 1; i <= extra; i++)
		if ((p[i] & 0xc0) != 0x80)
			extra = 0;
	if (extra) {
		c &= 0x3f >> extra;
		for (int i = 1; i <= extra; i++)
			c = c << 6 | (p[i] & 0x3f);
	}
	*s = p + 1 + extra;
	return c;
}

/* The glyphs of the string, placed as POV-Ray places them (ProcessNewTTF): the
 * first with its left edge at 0, each next one advance (and kerning) further,
 * offset added after each; the left bearing is taken as the glyph's xMin. */
static int text_glyphs(FT_Face face, const char *str, const double offset[3], struct build *b, unsigned *bad)
{
	FT_Outline_Funcs funcs = { .move_to = move_to, .line_to = line_to, .conic_to = conic_to, .cubic_to = cubic_to };
	double scale = 1.0 / face->units_per_EM, total[2] = { 0, 0 };
	FT_UInt last = 0;
	const unsigned char *s = (const unsigned char *)str;
	for (int i = 0; *s; i++) {
		FT_UInt g = FT_Get_Char_Index(face, next_char(&s));
		if (FT_Load_Glyph(face, g, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP)) {
			*bad = g;
			return -1;
		}
		FT_GlyphSlot slot = face->glyph;
		FT_BBox box;
		FT_Outline_Get_CBox(&slot->outline, &box);
		double xmin = slot->outline.n_points ? box.xMin : 0, adv = slot->advance.x;
		struct glyph_walk w = { .b = b, .scale = scale };
		if (i == 0) {
			w.x = -xmin * scale;
			total[0] = (adv - xmin) * scale;
		} else {
			FT_Vector k = { 0, 0 };
			if (FT_HAS_KERNING(face))
				FT_Get_Kerning(face, last, g, FT_KERNING_UNSCALED, &k);
			w.x = total[0] + k.x * scale;
			w.y = total[1];
			total[0] += (adv + k.x) * scale;
		}
		total[0] += offset[0];
		total[1] += offset[1];
		start_glyph(b);
		FT_Outline_Decompose(&slot->outline, &funcs, &w);
		close_contour(&w);
		last = g;
	}
	start_glyph(b);   /* the end of the last */
	b->ol.n_glyphs--;
	return 0;
}

/* FreeType runs in a child process (src/loader.h): a font with a broken table
 * may crash or hang it, and that must be an error at the text, not eclat's end.
 * The child sends the outline back: its edges and where each glyph starts. */
enum { FONT_OK, FONT_NOT_A_FONT, FONT_NO_GLYPH };

struct font_job {
	const char *path, *str;
	const double *offset;
	int answer;             /* FONT_ */
	unsigned bad_glyph;     /* FONT_NO_GLYPH's */
	struct build b;
};

/* The outline's counts are capped so that a child gone wrong cannot make eclat
 * allocate without bound (a glyph is at most a few thousand edges, and the
 * string is the scene's). */
#define FONT_MAX_EDGES (1 << 26)

static int font_work(int fd, void *arg)
{
	struct font_job *j = arg;
	FT_Library lib;
	FT_Face face;
	int head[4] = { FONT_NOT_A_FONT, 0, 0, 0 };   /* answer, bad glyph, edges, glyphs */
	if (FT_Init_FreeType(&lib) == 0) {
		if (FT_New_Face(lib, j->path, 0, &face) == 0) {
			unsigned bad = 0;
			head[0] = text_glyphs(face, j->str, j->offset, &j->b, &bad) ? FONT_NO_GLYPH : FONT_OK;
			head[1] = (int)bad;
			FT_Done_Face(face);
		}
		FT_Done_FreeType(lib);
	}
	if (head[0] == FONT_OK) {
		head[2] = j->b.ol.n_edges;
		head[3] = j->b.ol.n_glyphs;
	}
	return loader_write(fd, head, sizeof head) ||
	       (head[2] && loader_write(fd, j->b.ol.edge, (size_t)head[2] * sizeof *j->b.ol.edge)) ||
	       (head[0] == FONT_OK && loader_write(fd, j->b.ol.glyph, ((size_t)head[3] + 1) * sizeof *j->b.ol.glyph));
}

static int font_take(int fd, void *arg, char *err, size_t errlen)
{
	(void)err;
	(void)errlen;
	struct font_job *j = arg;
	int head[4];
	if (loader_read(fd, head, sizeof head))
		return -2;
	j->answer = head[0];
	j->bad_glyph = (unsigned)head[1];
	if (head[0] != FONT_OK)
		return 0;
	if (head[2] < 0 || head[2] > FONT_MAX_EDGES || head[3] < 0 || head[3] > FONT_MAX_EDGES)
		return -2;
	j->b.ol.n_edges = head[2];
	j->b.ol.n_glyphs = head[3];
	j->b.ol.edge = eval_xrealloc(NULL, ((size_t)head[2] + 1) * sizeof *j->b.ol.edge);
	j->b.ol.glyph = eval_xrealloc(NULL, ((size_t)head[3] + 1) * sizeof *j->b.ol.glyph);
	if ((head[2] && loader_read(fd, j->b.ol.edge, (size_t)head[2] * sizeof *j->b.ol.edge)) ||
	    loader_read(fd, j->b.ol.glyph, ((size_t)head[3] + 1) * sizeof *j->b.ol.glyph))
		return -2;
	for (int g = 0; g <= head[3]; g++)   /* prism.c indexes edges by these */
		if (j->b.ol.glyph[g] < 0 || j->b.ol.glyph[g] > head[2] || (g && j->b.ol.glyph[g] < j->b.ol.glyph[g - 1]))
			return -2;
	return 0;
}

/* A text's outline read once per font, string and offset: a scene that writes
 * the same letters many times (POV-Ray's stacker blocks: 1,914 texts) starts
 * FreeType's child once for each, and the copies share the scene's outline.
 * At most FONT_CACHE entries, the first ones. */
#define FONT_CACHE 4096

struct eval_font {
	char *path, *str;
	double offset[3];
	int outline;
};

static int font_cached(const struct eval *e, const char *path, const char *str, const double offset[3])
{
	for (int i = 0; i < e->n_fonts; i++) {
		const struct eval_font *f = &e->fonts[i];
		if (strcmp(f->path, path) == 0 && strcmp(f->str, str) == 0 && f->offset[0] == offset[0] &&
		    f->offset[1] == offset[1] && f->offset[2] == offset[2])
			return f->outline;
	}
	return -1;
}

static void font_remember(struct eval *e, const char *path, const char *str, const double offset[3], int outline)
{
	if (e->n_fonts >= FONT_CACHE)
		return;
	e->fonts = eval_xrealloc(e->fonts, (size_t)(e->n_fonts + 1) * sizeof *e->fonts);
	e->fonts[e->n_fonts++] = (struct eval_font){ eval_xstrdup(path), eval_xstrdup(str),
		                                     { offset[0], offset[1], offset[2] }, outline };
}

void eval_outline_free(struct eval *e)
{
	for (int i = 0; i < e->n_fonts; i++) {
		free(e->fonts[i].path);
		free(e->fonts[i].str);
	}
	free(e->fonts);
	e->fonts = NULL;
	e->n_fonts = 0;
}

static int text_args(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	int err = 0;
	const ast_node *item = eval_next(c, &err);
	char *font = NULL, *str = NULL;
	src_loc font_loc = item ? item->loc : b->loc;
	if (item && item->kind == AST_IDENT && strcmp(item->str, AST_WORD_TTF) == 0) {
		const ast_node *arg = eval_next_expr(c, &err);
		if (!arg || eval_expect_string(e, arg, &font)) {
			if (!arg && !err)
				eval_error(e, item->loc, "ttf needs the name of a font file");
			return -1;
		}
		font_loc = arg->loc;
	} else if (item && item->kind == AST_IDENT && strcmp(item->str, AST_WORD_INTERNAL) == 0) {
		double n;
		if (next_float(e, c, b, "a font number after internal", &n))
			return -1;
		font = eval_xstrdup(internal_font(eval_int_of(n)));
	} else {
		if (!err)
			eval_error(e, item ? item->loc : b->loc, "text needs ttf \"Font\" or internal N first");
		return -1;
	}
	const ast_node *arg = eval_next_expr(c, &err);
	double depth, offset[3] = { 0, 0, 0 };
	if (!arg) {
		if (!err)
			eval_error(e, b->loc, "text needs a string after its font");
		free(font);
		return -1;
	}
	if (eval_expect_string(e, arg, &str) || next_float(e, c, b, "a thickness and an offset", &depth)) {
		free(font);
		free(str);
		return -1;
	}
	const ast_node *off = eval_next_expr(c, &err);
	if (!off || eval_expect_vector(e, off, offset)) {
		if (!off && !err)
			eval_error(e, b->loc, "text needs an offset vector after its thickness");
		free(font);
		free(str);
		return -1;
	}
	o->radius = depth;
	char *path = eval_find_file(e, font_loc.file, font);
	if (!path && !strchr(font, '.')) {   /* POV-Ray adds .ttf to a name without one: ttf "cyrvetic" */
		size_t n = strlen(font);
		char *with = malloc(n + 5);
		if (with) {
			memcpy(with, font, n);
			memcpy(with + n, ".ttf", 5);
			path = eval_find_file(e, font_loc.file, with);
			free(with);
		}
	}
	int rc = -1;
	if (!path) {
		eval_error(e, font_loc, "cannot find the font file '%s'", font);
	} else if (eval_access(e, path, false, font_loc, "text")) {
		/* refused, and said so */
	} else if ((o->outline = font_cached(e, path, str, offset)) >= 0) {
		rc = 0;
	} else {
		struct font_job j = { .path = path, .str = str, .offset = offset };
		char why[512];
		const char *not_file = loader_not_a_file(path);
		if (not_file)
			eval_error(e, font_loc, "cannot read the font '%s': %s", font, not_file);
		else if (loader_run("FreeType", e->opt->mesh_time_limit, font_work, font_take, &j, why, sizeof why))
			eval_error(e, font_loc, "cannot read the font '%s': %s", font, why);
		else if (j.answer == FONT_NOT_A_FONT)
			eval_error(e, font_loc, "'%s' is not a font FreeType can read", font);
		else if (j.answer == FONT_NO_GLYPH)
			eval_error(e, arg->loc, "text: the font has no outline for glyph %u", j.bad_glyph);
		else {
			store(e, &j.b, o);
			font_remember(e, path, str, offset, o->outline);
			rc = 0;
		}
		if (rc) {
			free(j.b.ol.edge);
			free(j.b.ol.glyph);
		}
	}
	free(path);
	free(font);
	free(str);
	return rc;
}

/* ---- sor and lathe (src/revolve.h): their points as written ---- */

static void store_points(struct eval *e, double (*P)[2], int n, scene_object *o)
{
	scene_outline ol = { .edge = eval_xrealloc(NULL, (n ? n : 1) * sizeof *ol.edge), .n_edges = n };
	for (int i = 0; i < n; i++) {
		ol.edge[i][0] = P[i][0];
		ol.edge[i][1] = P[i][1];
		ol.edge[i][2] = ol.edge[i][3] = 0;
	}
	o->outline = scene_add_outline(e->s, &ol);
}

static int read_points(struct eval *e, struct cursor *c, const ast_node *b, int n, double (**out)[2])
{
	double (*P)[2] = eval_xrealloc(NULL, (n ? n : 1) * sizeof *P);
	for (int i = 0; i < n; i++) {
		double p[3];
		if (next_point(e, c, b, i, n, 2, p)) {
			free(P);
			return -1;
		}
		P[i][0] = p[0];
		P[i][1] = p[1];
	}
	*out = P;
	return 0;
}

/* sor { Number, <Point>... [open] [sturm] } (open and sturm are read with the modifiers) */
static int sor_args(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	int n;
	double (*P)[2];
	if (count_arg(e, c, b, &n))
		return -1;
	if (n < 4) {
		eval_error(e, b->loc, "a sor needs at least four points, not %d", n);
		return -1;
	}
	if (read_points(e, c, b, n, &P))
		return -1;
	const char *bad = revolve_sor_points((const double (*)[2])P, n);
	if (bad) {
		eval_error(e, b->loc, "%s", bad);
		free(P);
		return -1;
	}
	store_points(e, P, n, o);
	free(P);
	return 0;
}

/* lathe { [linear_spline | quadratic_spline | cubic_spline | bezier_spline] Number, <Point>... [sturm] } */
static int lathe_args(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	static const char *const splines[] = { "linear_spline", "quadratic_spline", "cubic_spline", "bezier_spline" };
	int spline = REVOLVE_LINEAR, err = 0, n;
	const ast_node *item = eval_next(c, &err);
	if (err)
		return -1;
	bool word = false;
	if (item && item->kind == AST_IDENT && !eval_lookup(e, item->str))
		for (int i = 0; i < 4; i++)
			if (strcmp(item->str, splines[i]) == 0) {
				spline = i;
				word = true;
			}
	if (item && !word)
		eval_unget(c, item);
	if (count_arg(e, c, b, &n))
		return -1;
	o->param[0] = spline;
	double (*P)[2];
	if (n < 2 || n > 10000000) {
		eval_error(e, b->loc, "%s, not %d", revolve_lathe_points(spline, NULL, 0), n);
		return -1;
	}
	if (read_points(e, c, b, n, &P))
		return -1;
	const char *bad = revolve_lathe_points(spline, (const double (*)[2])P, n);
	if (bad) {
		eval_error(e, b->loc, bad == revolve_lathe_points(spline, NULL, 0) ? "%s, not %d" : "%s", bad, n);
		free(P);
		return -1;
	}
	bool ends = spline != REVOLVE_QUADRATIC ? P[0][0] < 0 || P[n - 1][0] < 0 : P[n - 1][0] < 0;
	if (spline != REVOLVE_CUBIC && ends)
		eval_warning(e, b->loc, "lathe with a first or last point with an x value < 0 (POV-Ray 3.7 warns: "
		             "it leads to artifacts)");
	store_points(e, P, n, o);
	free(P);
	return 0;
}

int eval_outline_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	switch (o->shape) {
	case SHAPE_POLYGON: return polygon_args(e, c, b, o);
	case SHAPE_PRISM: return prism_args(e, c, b, o);
	case SHAPE_TEXT: return text_args(e, c, b, o);
	case SHAPE_SOR: return sor_args(e, c, b, o);
	case SHAPE_LATHE: return lathe_args(e, c, b, o);
	case SHAPE_ISOSURFACE: return eval_isosurface_arguments(e, c, b, o);
	case SHAPE_BLOB: return eval_blob_arguments(e, c, b, o);
	case SHAPE_SPHERE_SWEEP: return eval_sweep_arguments(e, c, b, o);
	case SHAPE_PARAMETRIC: return eval_parametric_arguments(e, c, b, o);
	case SHAPE_HEIGHT_FIELD: return eval_height_field_arguments(e, c, b, o);
	case SHAPE_BICUBIC_PATCH: return eval_bicubic_arguments(e, c, b, o);
	case SHAPE_JULIA_FRACTAL: return eval_julia_fractal_arguments(e, c, b, o);
	case SHAPE_POLY:
	case SHAPE_CUBIC:
	case SHAPE_QUARTIC:
	case SHAPE_POLYNOMIAL: return eval_poly_arguments(e, c, b, o);
	default:
		eval_error(e, b->loc, "%s has no reader of its arguments", b->str);
		return -1;
	}
}
