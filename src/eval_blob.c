/* eval_blob.c: what a blob { } says before its object modifiers, in POV-Ray
 * 3.7's order and with its defaults (Parse_Blob): threshold (1), components
 * in the old syntax (component Strength, Radius, <Centre>) and the new
 * (sphere { <Centre>, Radius, [strength] S [MODIFIERS] }, cylinder { <A>,
 * <B>, Radius, [strength] S [MODIFIERS] }, each with its own transformations
 * and texture), sturm and hierarchy, in any order. The components go to
 * scene.blobs (src/shape_blob.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"

static const char *block_name(const ast_node *b)
{
	return b->kw == KW_UNKNOWN ? b->str : ast_keyword_name(b->kw);
}

/* A component's own modifiers, POV-Ray 3.7's Parse_Blob_Element_Mods:
 * transformations move its field (into *xf, its space to the blob's) and its
 * texture when written after it; texture, pigment, normal and finish make its
 * own texture, which starts from the #default (not from the blob's texture,
 * which only the components without one show). A second texture { } is a
 * layer on the first, as on an object. */
static int modifiers(struct eval *e, struct cursor *c, scene_blob_part *p, xform *xf)
{
	scene_material m = e->default_mat;
	bool textured = false;
	int err = 0;
	const ast_node *item;
	while ((item = eval_next(c, &err)) != NULL) {
		xform step = scene_xform_identity();
		int k = eval_transform_item(e, c, item, &step);
		if (k < 0)
			return -1;
		if (k > 0) {
			*xf = scene_xform_then(xf, &step);
			if (textured)
				m.tex_xf = scene_xform_then(&m.tex_xf, &step);
			continue;
		}
		if (item->kind != AST_BLOCK ||
		    (item->kw != KW_TEXTURE && item->kw != KW_PIGMENT && item->kw != KW_NORMAL && item->kw != KW_FINISH))
			return eval_not_valid(e, item, "a blob component");
		if (item->kw == KW_TEXTURE) {
			value v;
			if (eval_material_value(e, item, &v))
				return -1;
			eval_apply_texture(e, item->loc, &m, textured, &v.mat);
			eval_value_free(&v);
		} else if (eval_material_block(e, item, &m)) {
			return -1;
		}
		textured = true;
	}
	if (err)
		return -1;
	if (textured)
		p->texture = 1 + scene_add_texture(e->s, &m);
	return 0;
}

/* The component moved by xf: a, b and r moved along when xf keeps the ratios
 * of distances (a rotation, a translation, a uniform scale, as POV-Ray moves a
 * sphere component's centre and radius), else the map back kept (POV-Ray's
 * ellipsoid, and its cylinders' own space). */
static int place(struct eval *e, const ast_node *b, scene_blob_part *p, const xform *xf)
{
	double g[3][3], s2 = 0, off = 0;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) {
			g[i][j] = 0;
			for (int k = 0; k < 3; k++)
				g[i][j] += xf->m[k][i] * xf->m[k][j];
		}
	for (int i = 0; i < 3; i++)
		s2 += g[i][i] / 3;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			off = fmax(off, fabs(g[i][j] - (i == j ? s2 : 0)));
	if (s2 > 0 && off <= 1e-12 * s2) {
		scene_xform_point(xf, p->a, p->a);
		scene_xform_point(xf, p->b, p->b);
		p->r *= sqrt(s2);
		return 0;
	}
	double det = xf->m[0][0] * (xf->m[1][1] * xf->m[2][2] - xf->m[1][2] * xf->m[2][1]) -
	             xf->m[0][1] * (xf->m[1][0] * xf->m[2][2] - xf->m[1][2] * xf->m[2][0]) +
	             xf->m[0][2] * (xf->m[1][0] * xf->m[2][1] - xf->m[1][1] * xf->m[2][0]);
	if (!(fabs(det) > 1e-30)) {
		eval_error(e, b->loc, "a blob component's transformation is singular (a matrix that flattens it?)");
		return -1;
	}
	p->xformed = true;
	p->xf = *xf;
	p->inv = eval_xform_inverse(xf);
	return 0;
}

/* sphere { <C>, R, [strength] S [MODIFIERS] } or cylinder { <A>, <B>, R, [strength] S [MODIFIERS] } */
static int component(struct eval *e, const ast_node *b, bool cylinder, scene_blob_part *p)
{
	struct cursor c;
	int err = 0, rc = -1;
	eval_cursor_init(&c, e, b);
	const ast_node *arg[4] = { 0 }, *negated = NULL;
	int n = cylinder ? 4 : 3;
	for (int i = 0; i < n; i++) {
		arg[i] = eval_next(&c, &err);
		const char *w = arg[i] && i == n - 1 ? eval_word_item(arg[i], &negated) : NULL;
		if (w && strcmp(w, AST_WORD_STRENGTH) == 0)   /* strength S, or strength -S */
			arg[i] = negated ? negated : eval_next(&c, &err);
		else
			negated = NULL;
		if (!arg[i] || !AST_IS_EXPRESSION(arg[i]->kind))
			break;
	}
	if (!arg[n - 1] || !AST_IS_EXPRESSION(arg[n - 1]->kind)) {
		if (!err)
			eval_error(e, b->loc, "a blob's %s needs %s and a strength", block_name(b),
			           cylinder ? "two ends, a radius" : "a centre, a radius");
	} else if (eval_expect_vector(e, arg[0], p->a) == 0 &&
	           (cylinder ? eval_expect_vector(e, arg[1], p->b) : 0) == 0 &&
	           eval_expect_float(e, arg[n - 2], &p->r) == 0 && eval_expect_float(e, arg[n - 1], &p->s) == 0) {
		rc = 0;
		if (negated)
			p->s = -p->s;
		if (!cylinder)
			memcpy(p->b, p->a, sizeof p->a);
		double d2 = 0;
		for (int k = 0; k < 3; k++)
			d2 += (p->b[k] - p->a[k]) * (p->b[k] - p->a[k]);
		xform xf = scene_xform_identity();
		if (cylinder && !(sqrt(d2) > 1e-10)) {   /* POV-Ray's EPSILON */
			eval_error(e, b->loc, "degenerate cylindrical component in blob (its ends are the same point)");
			rc = -1;
		} else if (modifiers(e, &c, p, &xf) || place(e, b, p, &xf)) {
			rc = -1;
		}
	}
	eval_cursor_free(&c);
	return rc || err ? -1 : 0;
}

static void add_part(scene_blob *bl, const scene_blob_part *p, int *cap)
{
	if (bl->n_parts == *cap) {
		*cap = *cap ? 2 * *cap : 8;
		bl->part = eval_xrealloc(bl->part, *cap * sizeof *bl->part);
	}
	bl->part[bl->n_parts++] = *p;
}

int eval_blob_arguments(struct eval *e, struct cursor *c, const ast_node *b, scene_object *o)
{
	scene_blob bl = { .threshold = 1 };
	int err = 0, rc = 0, cap = 0;
	const ast_node *item;
	while (rc == 0 && (item = eval_next(c, &err)) != NULL) {
		const ast_node *neg;
		const char *w = eval_word_item(item, &neg);
		scene_blob_part p = { 0 };
		if (w && strcmp(w, AST_WORD_THRESHOLD) == 0) {
			rc = eval_word_float(e, c, item, neg, &bl.threshold);
		} else if (w && strcmp(w, AST_WORD_COMPONENT) == 0) {   /* component S, R, <C> */
			const ast_node *r = NULL, *at = NULL;
			rc = eval_word_float(e, c, item, neg, &p.s);
			if (rc == 0 && ((r = eval_next_expr(c, &err)) == NULL || (at = eval_next_expr(c, &err)) == NULL)) {
				if (!err)
					eval_error(e, item->loc, "a blob's component needs a strength, a radius and a centre");
				rc = -1;
			}
			if (rc == 0 && (eval_expect_float(e, r, &p.r) || eval_expect_vector(e, at, p.a)))
				rc = -1;
			if (rc == 0) {
				memcpy(p.b, p.a, sizeof p.a);
				add_part(&bl, &p, &cap);
			}
		} else if (item->kind == AST_BLOCK && (item->kw == KW_SPHERE || strcmp(block_name(item), "cylinder") == 0)) {
			rc = component(e, item, item->kw != KW_SPHERE, &p);
			if (rc == 0)
				add_part(&bl, &p, &cap);
		} else if (w && strcmp(w, AST_WORD_STURM) == 0 && !neg) {
			o->shape_flags |= SHAPE_STURM;
		} else if (w && strcmp(w, AST_WORD_HIERARCHY) == 0 && !neg) {   /* a bounding tree POV-Ray builds: no image change */
			const ast_node *on = eval_next_optional(c, &err);
			double v;
			if (on && eval_expect_float(e, on, &v))
				rc = -1;
		} else {
			eval_unget(c, item);   /* the object modifiers */
			break;
		}
	}
	if (rc || err) {
		free(bl.part);
		return -1;
	}
	if (bl.n_parts == 0)
		eval_warning(e, b->loc, "a blob with no components draws nothing");
	for (int j = 0; j < bl.n_parts; j++)
		if (!(bl.part[j].r > 0)) {
			eval_error(e, b->loc, "a blob component's radius must be above 0, not %g", bl.part[j].r);
			free(bl.part);
			return -1;
		}
	o->poly = scene_add_blob(e->s, &bl);
	return 0;
}
