/* eval_object.c: objects (sphere, box, plane, triangles, meshes, union, object),
 * their modifiers, and transformations. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"
#include "shape.h"
#include "csg.h"
#include "mesh_io.h"

/* "a sphere", "an object": for the messages. */
static const char *with_article(const char *name, char *out, size_t size)
{
	snprintf(out, size, "%s %s", strchr("aeiou", name[0]) ? "an" : "a", name);
	return out;
}

/* ---- transformations ---- */

static bool invert3(const double m[3][3], double inv[3][3])
{
	double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
	             m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
	             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
	if (fabs(det) < 1e-300)
		return false;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) {
			int a = (j + 1) % 3, b = (j + 2) % 3, c = (i + 1) % 3, d = (i + 2) % 3;
			inv[i][j] = (m[a][c] * m[b][d] - m[a][d] * m[b][c]) / det;
		}
	return true;
}

xform eval_xform_inverse(const xform *t)
{
	double m[3][3], inv[3][3];
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			m[i][j] = t->m[i][j];
	xform r = scene_xform_identity();
	if (!invert3(m, inv))
		return r;
	for (int i = 0; i < 3; i++) {
		r.m[i][3] = 0;
		for (int j = 0; j < 3; j++) {
			r.m[i][j] = inv[i][j];
			r.m[i][3] -= inv[i][j] * t->m[j][3];
		}
	}
	return r;
}

static bool singular(const xform *t)
{
	double m[3][3], inv[3][3];
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			m[i][j] = t->m[i][j];
	return !invert3(m, inv);
}

/* matrix <A, B, C,  D, E, F,  G, H, I,  J, K, L>: POV-Ray's row vector times the
 * matrix: x' = A x + D y + G z + J, and so on. */
static int matrix(struct eval *e, const ast_node *arg, xform *out)
{
	if (arg->kind != AST_VECTOR || arg->n_kids != 12) {
		eval_error(e, arg->loc, "matrix takes a vector of 12 numbers, <A, B, C, D, E, F, G, H, I, J, K, L>");
		return -1;
	}
	double m[12];
	for (int i = 0; i < 12; i++)
		if (eval_expect_float(e, arg->kids[i], &m[i]))
			return -1;
	for (int j = 0; j < 3; j++) {
		for (int i = 0; i < 3; i++)
			out->m[j][i] = m[3 * i + j];
		out->m[j][3] = m[9 + j];
	}
	return 0;
}

static int transform_block(struct eval *e, const ast_node *b, xform *out);

/* transform Name, transform { ... } */
static int transform_arg(struct eval *e, const ast_node *item, xform *out)
{
	if (item->kind == AST_BLOCK)
		return transform_block(e, item, out);
	value v;
	if (eval_expr(e, item->kids[0], &v))
		return -1;
	if (v.kind != V_TRANSFORM) {
		eval_error(e, item->kids[0]->loc, "expected a transform, found %s", eval_kind_name(v.kind));
		eval_value_free(&v);
		return -1;
	}
	*out = v.xf;
	return 0;
}

/* scale: a component of 0 is changed to 1, as POV-Ray does. */
static xform scale(struct eval *e, const ast_node *arg, double v[3])
{
	for (int i = 0; i < 3; i++)
		if (v[i] == 0) {
			eval_warning(e, arg->loc, "scale by 0 changed to 1, as POV-Ray does");
			v[i] = 1;
		}
	return scene_xform_scale(v);
}

/* translate V | rotate V | scale V | matrix <...> | transform T | transform { ... }:
 * 1 when item is one (t updated), 0 when not, -1 on error. */
int eval_transform_item(struct eval *e, struct cursor *c, const ast_node *item, xform *t)
{
	(void)c;
	if ((item->kind != AST_ARG && item->kind != AST_BLOCK) || item->kw < 0)
		return 0;
	xform step;
	double v[3];
	switch (item->kw) {
	case KW_TRANSLATE: case KW_ROTATE: case KW_SCALE:
		if (item->kind != AST_ARG) {
			eval_error(e, item->loc, "'%s' takes a vector, not a block", ast_keyword_name(item->kw));
			return -1;
		}
		if (eval_expect_vector(e, item->kids[0], v))
			return -1;
		step = item->kw == KW_TRANSLATE ? scene_xform_translate(v)
		     : item->kw == KW_ROTATE ? scene_xform_rotate(v) : scale(e, item->kids[0], v);
		break;
	case KW_MATRIX:
		step = scene_xform_identity();
		if (item->kind != AST_ARG || matrix(e, item->kids[0], &step))
			return -1;
		break;
	case KW_TRANSFORM:
		if (transform_arg(e, item, &step))
			return -1;
		break;
	default:
		return 0;
	}
	*t = scene_xform_then(t, &step);
	return 1;
}

/* transform { [TRANSFORM_IDENTIFIER] [TRANSFORMATION...] [inverse] } */
static int transform_block(struct eval *e, const ast_node *b, xform *out)
{
	struct cursor c;
	int err = 0, rc = 0, inverse = 0;
	const ast_node *item;
	*out = scene_xform_identity();
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		if (item->kind == AST_FLAG && item->kw == KW_INVERSE) {
			inverse = 1;
			continue;
		}
		if (AST_IS_EXPRESSION(item->kind)) {
			value v;
			if (eval_expr(e, item, &v))
				rc = -1;
			else if (v.kind != V_TRANSFORM)
				rc = eval_not_valid(e, item, "a transform");
			else
				*out = scene_xform_then(out, &v.xf);
			eval_value_free(&v);
			continue;
		}
		int k = eval_transform_item(e, &c, item, out);
		rc = k < 0 ? -1 : k == 0 ? eval_not_valid(e, item, "a transform") : 0;
	}
	eval_cursor_free(&c);
	if (rc || err)
		return -1;
	if (inverse) {
		if (singular(out)) {
			eval_error(e, b->loc, "this transform cannot be inverted");
			return -1;
		}
		*out = eval_xform_inverse(out);
	}
	return 0;
}

static void transform_light(struct lightval *l, const xform *t)
{
	scene_light *s = &l->light;
	scene_xform_point(t, s->position, s->position);
	scene_xform_point(t, s->point_at, s->point_at);
	scene_xform_vector(t, s->axis1, s->axis1);
	scene_xform_vector(t, s->axis2, s->axis2);
	for (int i = 0; i < l->n_looks; i++)
		l->looks[i].xf = scene_xform_then(&l->looks[i].xf, t);
}

/* A texture moves with the transformations written after it (not those before). */
static void transform_objval(struct objval *o, const xform *t)
{
	for (int i = 0; i < o->n_objs; i++) {
		o->objs[i].xf = scene_xform_then(&o->objs[i].xf, t);
		if (o->objs[i].textured)
			o->objs[i].material.tex_xf = scene_xform_then(&o->objs[i].material.tex_xf, t);
		o->objs[i].material.interior_xf = scene_xform_then(&o->objs[i].material.interior_xf, t);
	}
	if (o->has_mat)
		o->mat.tex_xf = scene_xform_then(&o->mat.tex_xf, t);
	if (o->has_mat || o->has_interior)
		o->mat.interior_xf = scene_xform_then(&o->mat.interior_xf, t);
	for (int i = 0; i < o->n_lights; i++)
		transform_light(&o->lights[i], t);
	if (o->bound)
		transform_objval(o->bound, t);
}

/* ---- modifiers ---- */

/* m takes tex's texture and keeps its own interior: an object's texture and
 * its interior are given, and passed down to a union's parts, apart. */
static void take_texture(scene_material *m, const scene_material *tex)
{
	scene_material own = *m;
	*m = *tex;
	eval_apply_value(&(value){ .kind = V_INTERIOR, .mat = own }, m);
	m->interior_xf = own.interior_xf;
}

/* A union's texture goes to its parts that have none of their own, and its
 * interior to those without theirs (POV-Ray's Post_Process). This happens
 * when the union is used (placed in the scene or in another union), so that
 * object { U pigment { ... } } still changes the texture of U's bare parts. */
static void resolve_texture(struct objval *o)
{
	for (int i = 0; o->compound && i < o->n_objs; i++) {
		scene_object *c = &o->objs[i];
		if (o->has_mat && !c->textured) {
			if (c->interior_set)
				take_texture(&c->material, &o->mat);
			else
				c->material = o->mat;
			c->textured = true;
		}
		if (o->has_interior && !c->interior_set) {
			eval_apply_value(&(value){ .kind = V_INTERIOR, .mat = o->mat }, &c->material);
			c->material.interior_xf = o->mat.interior_xf;
			c->interior_set = true;
		}
	}
	o->has_mat = o->has_interior = false;
}

/* The one shape whose texture and interior an object's modifiers change (its
 * clipped_by shapes are not seen), or -1 for a compound's own. */
static int own_shape(const struct objval *o)
{
	int shape = -1, shapes = 0;
	for (int i = 0; !o->compound && i < o->n_objs; i++)
		if (!o->objs[i].clip) {
			shape = i;
			shapes++;
		}
	return shapes == 1 ? shape : -1;
}

/* The texture a pigment, finish or texture modifies: a single shape's own, else
 * the union's, which its bare parts take. */
static scene_material *target(struct eval *e, struct objval *o, bool *textured)
{
	int shape = own_shape(o);
	if (shape >= 0) {
		scene_material *m = &o->objs[shape].material;
		*textured = o->objs[shape].textured;
		if (!*textured)   /* POV-Ray copies the #default in effect now, not the one at the shape's making */
			eval_apply_value(&(value){ .kind = V_TEXTURE, .mat = e->default_mat }, m);
		o->objs[shape].textured = true;
		return m;
	}
	*textured = o->has_mat;
	if (!o->has_mat) {
		if (o->has_interior)
			take_texture(&o->mat, &e->default_mat);
		else
			o->mat = e->default_mat;
	}
	o->has_mat = true;
	return &o->mat;
}

/* The interior an interior modifies: a single shape's own, else the
 * compound's, for its parts that have none. It leaves the texture as it is:
 * a texture written after it replaces the default rather than layering on it. */
static scene_material *interior_target(struct eval *e, struct objval *o)
{
	int shape = own_shape(o);
	if (shape >= 0) {
		o->objs[shape].interior_set = true;
		return &o->objs[shape].material;
	}
	if (!o->has_mat && !o->has_interior)
		o->mat = e->default_mat;
	o->has_interior = true;
	return &o->mat;
}

/* ---- CSG ---- */

static int add_part(struct eval *e, const ast_node *item, struct objval *o);

/* Appends to p the formula of o's shapes, their leaf numbers moved up by
 * shift: a CSG object's program, a shape standing alone as one leaf, and
 * several of them combined by join (CSG_UNION for a union, which keeps their
 * inner surfaces; CSG_AND for the parts of a clip). Nothing is an empty part,
 * inside nowhere. */
static void csg_parts(const struct objval *o, csg_prog *p, int shift, int join)
{
	int parts = 0;
	for (int i = 0; i < o->n_objs;) {
		const struct objcsg *g = NULL;
		for (int k = 0; k < o->n_csgs; k++)
			if (o->csgs[k].first == i)
				g = &o->csgs[k];
		if (g) {
			csg_append(p, g->ops, g->n_ops, shift + i);
			i += g->n_leaves;
		} else {
			csg_push(p, CSG_LEAF, shift + i);
			i++;
		}
		if (++parts > 1)
			csg_push(p, join, 2);
	}
	if (parts == 0)
		csg_push(p, CSG_LEAF, CSG_NO_LEAF);
}

static void csg_formula(const struct objval *o, csg_prog *p, int shift)
{
	csg_parts(o, p, shift, CSG_UNION);
}

/* Makes all of o's shapes the leaves of one CSG object with program p. */
static void csg_group(struct objval *o, csg_prog *p, src_loc loc)
{
	for (int i = 0; i < o->n_csgs; i++)
		free(o->csgs[i].ops);
	o->csgs = eval_xrealloc(o->csgs, sizeof *o->csgs);
	o->csgs[0] = (struct objcsg){ .first = 0, .n_leaves = o->n_objs, .ops = p->ops, .n_ops = p->n, .loc = loc };
	o->n_csgs = 1;
}

/* inverse: the inside and the outside swap, which only CSG sees. */
static void csg_inverse(struct objval *o)
{
	csg_prog p = { 0 };
	csg_formula(o, &p, 0);
	csg_push(&p, CSG_NOT, 0);
	csg_group(o, &p, o->loc);
}

/* no_shadow, no_image, no_reflection, hollow [Bool], double_illuminate [Bool],
 * media_interaction [Bool] */
static int flag_item(struct eval *e, struct cursor *c, const ast_node *item, struct objval *o)
{
	static const struct { int kw, flag; } flags[] = {
		{ KW_NO_SHADOW, OBJ_NO_SHADOW }, { KW_NO_IMAGE, OBJ_NO_IMAGE },
		{ KW_NO_REFLECTION, OBJ_NO_REFLECTION }, { KW_HOLLOW, OBJ_HOLLOW },
		{ KW_DOUBLE_ILLUMINATE, OBJ_DOUBLE_ILLUMINATE },
	};
	int err = 0, flag = 0;
	for (size_t i = 0; i < sizeof flags / sizeof *flags; i++)
		if (flags[i].kw == item->kw)
			flag = flags[i].flag;
	if (item->kw == KW_INVERSE) {
		csg_inverse(o);
		return 0;
	}
	if (item->kw == KW_MEDIA_INTERACTION) {   /* an object's: whether media see it; lights' are read */
		eval_warn_once(e, item->loc, "object media_interaction",
		               "an object's 'media_interaction' is not supported yet; ignored");
		const ast_node *arg = eval_next_optional(c, &err);
		double ignored;
		return arg && eval_expect_float(e, arg, &ignored) ? -1 : err ? -1 : 0;
	}
	if (!flag)
		return 1;
	double on = 1;
	const ast_node *arg = eval_next_optional(c, &err);
	if (arg && eval_expect_float(e, arg, &on))
		return -1;
	for (int i = 0; i < o->n_objs; i++)
		o->objs[i].flags = eval_truth(on) ? o->objs[i].flags | flag : o->objs[i].flags & ~flag;
	return 0;
}

/* pigment, finish, normal, interior modify the object's texture; a texture or a
 * material replaces it, or is layered on the one it has (eval_apply_texture). */
/* The object's uv_mapping on m: placed by the transformations m has now,
 * not by the object's after it. */
static void object_uv(scene_material *m)
{
	m->uv = SCENE_UV_OBJECT;
	m->uv_xf = m->tex_xf;
}

static int material_modifier(struct eval *e, const ast_node *item, struct objval *o)
{
	if (item->kw == KW_INTERIOR)
		return eval_material_block(e, item, interior_target(e, o));
	bool textured;
	scene_material *m = target(e, o, &textured);
	if (item->kw == KW_MATERIAL) {   /* its interior is the object's own from now */
		int shape = own_shape(o);
		if (shape >= 0)
			o->objs[shape].interior_set = true;
		else
			o->has_interior = true;
	}
	if (item->kw != KW_TEXTURE && item->kw != KW_MATERIAL) {
		int rc = eval_material_block(e, item, m);
		if (o->uv)
			object_uv(m);
		return rc;
	}
	value v;
	if (eval_material_value(e, item, &v))
		return -1;
	eval_apply_texture(e, item->loc, m, textured, &v.mat);
	if (item->kw == KW_MATERIAL)
		eval_apply_value(&(value){ .kind = V_INTERIOR, .mat = v.mat }, m);
	if (o->uv)
		object_uv(m);
	return 0;
}

/* uv_mapping among an object's modifiers: the textures written after it see
 * the surface's <u, v, 0>; after one, POV-Ray's error. */
static int object_uv_mapping(struct eval *e, const ast_node *item, struct objval *o)
{
	bool textured = o->has_mat;
	for (int i = 0; !o->compound && i < o->n_objs; i++)
		textured |= !o->objs[i].clip && o->objs[i].textured;
	if (textured) {
		eval_error(e, item->loc, "uv_mapping must be written before the texture");
		return -1;
	}
	o->uv = true;
	e->s->uv_mapped = true;
	return 0;
}

/* interior_texture { TEXTURE_ITEMS }: the texture of the object's inner side,
 * moved by the object's transformations written after it. */
static int interior_texture(struct eval *e, const ast_node *item, struct objval *o)
{
	bool textured;
	scene_material *m = target(e, o, &textured);
	ast_node body = { .kind = AST_BLOCK, .kw = KW_TEXTURE, .loc = item->loc, .kids = item->kids,
	                  .n_kids = item->n_kids };
	value v;
	if (eval_material_value(e, &body, &v))
		return -1;
	m->interior_texture = 1 + scene_add_texture(e->s, &v.mat);
	m->interior_xf = scene_xform_identity();
	eval_value_free(&v);
	return 0;
}

static bool is_material_kw(int kw)
{
	return kw == KW_PIGMENT || kw == KW_FINISH || kw == KW_TEXTURE || kw == KW_NORMAL || kw == KW_INTERIOR ||
	       kw == KW_MATERIAL;
}

/* open and sturm, for the shapes whose class takes them (POV-Ray ignores sturm
 * where it means nothing, and so does eclat); 1 when item is neither. */
static int shape_flag(struct eval *e, const ast_node *item, struct objval *o)
{
	if (item->kind != AST_IDENT || eval_lookup(e, item->str))
		return 1;
	int flag = strcmp(item->str, AST_WORD_OPEN) == 0 ? SHAPE_OPEN : strcmp(item->str, AST_WORD_STURM) == 0 ? SHAPE_STURM : 0;
	if (!flag)
		return 1;
	bool taken = flag == SHAPE_STURM;
	for (int i = 0; i < o->n_objs; i++)
		if (shape_of(&o->objs[i])->flags & flag) {
			o->objs[i].shape_flags |= flag;
			taken = true;
		}
	return taken ? 0 : 1;
}

/* The objects of a bounded_by or clipped_by block, as one object value; a
 * clipped_by { bounded_by } takes the bounded_by written before it. */
static int clip_objects(struct eval *e, const ast_node *b, const struct objval *o, value *out)
{
	struct cursor c;
	int err = 0, rc = 0;
	const ast_node *item;
	*out = (value){ .kind = V_OBJECT, .obj = eval_objval_new(b->loc) };
	out->obj->compound = true;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		if (b->kw == KW_CLIPPED_BY && item->kind == AST_FLAG && item->kw == KW_BOUNDED_BY) {
			if (!o->bound) {
				eval_error(e, item->loc, "clipped_by { bounded_by } needs a bounded_by before it");
				rc = -1;
			} else {
				eval_objval_merge(out->obj, o->bound);
			}
		} else if (b->kw == KW_BOUNDED_BY && item->kind == AST_FLAG && item->kw == KW_CLIPPED_BY) {
			continue;   /* bounded_by { clipped_by }: the bound is the clip, which eclat needs not */
		} else if (eval_is_object_block(item)) {
			rc = add_part(e, item, out->obj);
		} else {
			rc = eval_not_valid(e, item, ast_keyword_name(b->kw));
		}
	}
	eval_cursor_free(&c);
	if (rc || err)
		eval_value_free(out);
	return rc || err ? -1 : 0;
}

/* bounded_by { OBJECT... }: POV-Ray's bound is a hint for speed, which eclat's
 * BVH does not need; it is kept for a clipped_by { bounded_by } after it, and
 * for a poly, which it may cut (eval_poly_bound). */
static int bounded_by(struct eval *e, const ast_node *b, struct objval *o)
{
	value v;
	if (clip_objects(e, b, o, &v))
		return -1;
	eval_objval_free(o->bound);
	o->bound = v.obj;
	return 0;
}

/* clipped_by { OBJECT... }: the object's surfaces are kept where they are
 * inside every clipping object, whose own surfaces are never seen: a CSG
 * intersection whose clipping leaves only answer inside tests. */
static int clipped_by(struct eval *e, const ast_node *b, struct objval *o)
{
	value v;
	if (clip_objects(e, b, o, &v))
		return -1;
	csg_prog p = { 0 };
	csg_formula(o, &p, 0);
	struct objval *c = v.obj;
	for (int i = 0; i < c->n_objs; i++)
		c->objs[i].clip = true;
	if (c->n_objs > 0) {   /* inside every clipping object: each part of the clip */
		csg_parts(c, &p, o->n_objs, CSG_AND);
		csg_push(&p, CSG_AND, 2);
	}
	for (int i = 0; i < c->n_objs; i++)
		eval_objval_add(o, &c->objs[i]);
	csg_group(o, &p, b->loc);
	eval_value_free(&v);
	return 0;
}

/* The items every object accepts after its own: transformations, textures,
 * flags; bounded_by and clipped_by are read and left out. */
static int object_modifier(struct eval *e, struct cursor *c, const ast_node *item, struct objval *o,
                           const char *where)
{
	xform t = scene_xform_identity();
	int rc = eval_transform_item(e, c, item, &t);
	if (rc != 0) {
		if (rc > 0)
			transform_objval(o, &t);
		return rc < 0 ? -1 : 0;
	}
	if (item->kind == AST_BLOCK && is_material_kw(item->kw))
		return material_modifier(e, item, o);
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && strcmp(item->str, AST_WORD_INTERIOR_TEXTURE) == 0)
		return interior_texture(e, item, o);
	if (item->kind == AST_FLAG && (rc = flag_item(e, c, item, o)) <= 0)
		return rc;
	if (item->kind == AST_FLAG && item->kw == KW_UV_MAPPING)
		return object_uv_mapping(e, item, o);
	if ((rc = shape_flag(e, item, o)) <= 0)
		return rc;
	if ((rc = eval_skip_pov_word(e, c, item)) <= 0)
		return rc;
	if (item->kind == AST_BLOCK && item->kw == KW_BOUNDED_BY)
		return bounded_by(e, item, o);
	if (item->kind == AST_BLOCK && item->kw == KW_CLIPPED_BY)
		return clipped_by(e, item, o);
	if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN && eval_pov_word(item->str) &&
	    strcmp(eval_pov_word(item->str), "object") != 0) {
		eval_warn_once(e, item->loc, item->str, "'%s' is not supported yet; ignored", item->str);
		return 0;
	}
	return eval_not_valid(e, item, where);
}

/* Reads the modifiers up to the end of the block. */
static int modifiers(struct eval *e, struct cursor *c, struct objval *o, const char *where)
{
	int err = 0;
	const ast_node *item;
	while ((item = eval_next(c, &err)) != NULL)
		if (object_modifier(e, c, item, o, where))
			return -1;
	return err ? -1 : 0;
}

/* ---- shapes ---- */

/* The positional arguments of a shape, as its class writes them (shape.h):
 * 'v' a corner or centre (p), 'n' a normal (n), 'f' a float (radius, then
 * param); after '|', the rest may be left out. */
static int arguments(struct eval *e, struct cursor *c, const ast_node *b, const shape_class *k, scene_object *o)
{
	int err = 0, np = 0, nn = 0, nf = 0;
	bool optional = false;
	for (const char *a = k->args; *a; a++) {
		if (*a == '|') {
			optional = true;
			continue;
		}
		/* an optional one is not a word such as open */
		const ast_node *arg = optional ? eval_next_optional(c, &err) : eval_next_expr(c, &err);
		if (!arg && err)
			return -1;
		if (!arg && optional)
			return 0;
		if (!arg) {
			const ast_node *next = eval_next(c, &err);
			char an[40];
			eval_error(e, next ? next->loc : b->loc, "%s needs %s", with_article(k->name, an, sizeof an), k->needs);
			return -1;
		}
		int rc;
		if (*a == 'f')
			rc = eval_expect_float(e, arg, nf == 0 ? &o->radius : &o->param[nf - 1]), nf++;
		else
			rc = eval_expect_vector(e, arg, *a == 'n' ? o->n[nn++] : o->p[np++]);
		if (rc)
			return -1;
	}
	return 0;
}

static scene_object new_object(struct eval *e, scene_shape shape, src_loc loc)
{
	return (scene_object){ .shape = shape, .xf = scene_xform_identity(), .material = e->default_mat,
	                       .mesh = -1, .loc = loc };
}

/* The shape's keyword: a keyword of the lexer's, or a word it does not know. */
static const char *block_name(const ast_node *b)
{
	return b->kw == KW_UNKNOWN ? b->str : ast_keyword_name(b->kw);
}

/* SHAPE { ARGUMENTS [OBJECT_MODIFIERS...] }, the arguments as the shape's class
 * says (src/shape_*.c): sphere { <Center>, Radius }, box { <Corner1>, <Corner2> }... */
static int shape(struct eval *e, const ast_node *b, value *out)
{
	const char *name = block_name(b);
	scene_shape kind;
	const shape_class *k = shape_named(name, &kind);
	scene_object o = new_object(e, kind, b->loc);
	struct cursor c;
	eval_cursor_init(&c, e, b);
	int rc = k->args ? arguments(e, &c, b, k, &o) : eval_outline_arguments(e, &c, b, &o);
	const char *bad = rc == 0 && k->check ? k->check(&o) : NULL;
	if (bad) {
		eval_error(e, b->loc, "%s", bad);
		rc = -1;
	}
	if (rc == 0) {
		*out = (value){ .kind = V_OBJECT, .obj = eval_objval_new(b->loc) };
		eval_objval_add(out->obj, &o);
		char a[40];
		rc = modifiers(e, &c, out->obj, with_article(name, a, sizeof a));
		if (rc)
			eval_value_free(out);
	}
	eval_cursor_free(&c);
	return rc;
}

/* ---- unions and object statements ---- */

static int add_part(struct eval *e, const ast_node *item, struct objval *o)
{
	value part;
	if (eval_object(e, item, &part))
		return -1;
	resolve_texture(part.obj);
	eval_objval_merge(o, part.obj);
	eval_value_free(&part);
	return 0;
}

/* union { OBJECT... [OBJECT_MODIFIERS...] } */
static int union_block(struct eval *e, const ast_node *b, value *out)
{
	struct cursor c;
	int err = 0, rc = 0, modifiers_seen = 0;
	const ast_node *item;
	*out = (value){ .kind = V_OBJECT, .obj = eval_objval_new(b->loc) };
	out->obj->compound = true;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		if (eval_is_object_block(item)) {
			if (modifiers_seen) {
				eval_error(e, item->loc, "the objects of a union come before its modifiers");
				rc = -1;
			} else {
				rc = add_part(e, item, out->obj);
			}
			continue;
		}
		modifiers_seen = 1;
		rc = object_modifier(e, &c, item, out->obj, "a union");
	}
	eval_cursor_free(&c);
	if (rc || err)
		eval_value_free(out);
	return rc || err ? -1 : 0;
}

/* The parts of a CSG block are complete: its program becomes the object's. */
static void csg_close(struct eval *e, const ast_node *b, const char *an, struct objval *o, csg_prog *p, int parts)
{
	if (parts < 2)
		eval_warning(e, b->loc, "%s should have at least 2 objects (POV-Ray's warning)", an);
	if (parts == 0)
		csg_push(p, CSG_LEAF, CSG_NO_LEAF);
	csg_group(o, p, b->loc);
	*p = (csg_prog){ 0 };
}

/* merge | intersection | difference { OBJECT... [OBJECT_MODIFIERS...] }: one
 * CSG object whose leaves are all the shapes of its parts. A difference is its
 * first part less the others; fewer than two parts draw what POV-Ray draws,
 * with its warning. */
static int csg_block(struct eval *e, const ast_node *b, value *out)
{
	const char *name = ast_keyword_name(b->kw);
	char an[40];
	with_article(name, an, sizeof an);
	int op = b->kw == KW_MERGE ? CSG_OR : CSG_AND;
	bool difference = b->kw == KW_DIFFERENCE;
	struct cursor c;
	int err = 0, rc = 0, modifiers_seen = 0, parts = 0;
	const ast_node *item;
	csg_prog p = { 0 };
	*out = (value){ .kind = V_OBJECT, .obj = eval_objval_new(b->loc) };
	out->obj->compound = true;
	eval_cursor_init(&c, e, b);
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		if (!eval_is_object_block(item)) {
			if (!modifiers_seen)
				csg_close(e, b, an, out->obj, &p, parts);
			modifiers_seen = 1;
			rc = object_modifier(e, &c, item, out->obj, name);
			continue;
		}
		if (modifiers_seen) {
			eval_error(e, item->loc, "the objects of a %s come before its modifiers", name);
			rc = -1;
			break;
		}
		value part;
		if (eval_object(e, item, &part)) {
			rc = -1;
			break;
		}
		resolve_texture(part.obj);
		csg_formula(part.obj, &p, out->obj->n_objs);
		if (difference && parts > 0)
			csg_push(&p, CSG_NOT, 0);
		if (++parts > 1)
			csg_push(&p, op, 2);
		eval_objval_merge(out->obj, part.obj);   /* its CSG objects are in p now: csg_close drops them */
		eval_value_free(&part);
	}
	if (rc == 0 && !err && !modifiers_seen)
		csg_close(e, b, an, out->obj, &p, parts);
	free(p.ops);
	eval_cursor_free(&c);
	if (rc || err)
		eval_value_free(out);
	return rc || err ? -1 : 0;
}

/* object { OBJECT_IDENTIFIER | OBJECT [OBJECT_MODIFIERS...] } */
static int object_statement(struct eval *e, const ast_node *b, value *out)
{
	struct cursor c;
	int err = 0, rc = -1;
	eval_cursor_init(&c, e, b);
	const ast_node *first = eval_next(&c, &err);
	if (!first) {
		if (!err)
			eval_error(e, b->loc, "object needs an object identifier or an object first");
	} else if (AST_IS_EXPRESSION(first->kind)) {
		rc = eval_expr(e, first, out);
		if (rc == 0 && out->kind != V_OBJECT) {
			eval_error(e, first->loc, "expected an object, found %s", eval_kind_name(out->kind));
			eval_value_free(out);
			rc = -1;
		}
	} else if (eval_is_object_block(first)) {
		rc = eval_object(e, first, out);
	} else {
		rc = eval_not_valid(e, first, "an object (expected an object identifier or an object first)");
	}
	if (rc == 0 && (rc = modifiers(e, &c, out->obj, "an object")) != 0)
		eval_value_free(out);
	eval_cursor_free(&c);
	return rc;
}

/* ---- meshes ---- */

struct mesh_build {
	scene_mesh m;
	int cap_v, cap_f, cap_nrm, cap_uv;
	bool smooth, uv;
};

static void mesh_vertex(struct mesh_build *mb, const double p[3])
{
	if (mb->m.n_v == mb->cap_v) {
		mb->cap_v = mb->cap_v ? 2 * mb->cap_v : 64;
		mb->m.v = eval_xrealloc(mb->m.v, mb->cap_v * sizeof *mb->m.v);
	}
	memcpy(mb->m.v[mb->m.n_v++], p, sizeof *mb->m.v);
}

static void mesh_normal(struct mesh_build *mb, const double n[3])
{
	if (mb->m.n_nrm == mb->cap_nrm) {
		mb->cap_nrm = mb->cap_nrm ? 2 * mb->cap_nrm : 64;
		mb->m.nrm = eval_xrealloc(mb->m.nrm, mb->cap_nrm * sizeof *mb->m.nrm);
	}
	double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
	for (int i = 0; i < 3; i++)
		mb->m.nrm[mb->m.n_nrm][i] = l > 0 ? n[i] / l : i == 0;
	mb->m.n_nrm++;
}

static void mesh_uv(struct mesh_build *mb, const double uv[2])
{
	if (mb->m.n_uv == mb->cap_uv) {
		mb->cap_uv = mb->cap_uv ? 2 * mb->cap_uv : 64;
		mb->m.uv = eval_xrealloc(mb->m.uv, mb->cap_uv * sizeof *mb->m.uv);
	}
	mb->m.uv[mb->m.n_uv][0] = uv[0];
	mb->m.uv[mb->m.n_uv][1] = uv[1];
	mb->m.n_uv++;
}

static void grow_faces(struct mesh_build *mb)
{
	if (mb->m.n_faces < mb->cap_f)
		return;
	mb->cap_f = mb->cap_f ? 2 * mb->cap_f : 64;
	mb->m.face = eval_xrealloc(mb->m.face, mb->cap_f * sizeof *mb->m.face);
	mb->m.face_mat = eval_xrealloc(mb->m.face_mat, mb->cap_f * sizeof *mb->m.face_mat);
	if (mb->m.face_nrm)
		mb->m.face_nrm = eval_xrealloc(mb->m.face_nrm, mb->cap_f * sizeof *mb->m.face_nrm);
	if (mb->m.face_uv)
		mb->m.face_uv = eval_xrealloc(mb->m.face_uv, mb->cap_f * sizeof *mb->m.face_uv);
}

/* The texture list of a mesh, each texture once. */
static int mesh_material(struct mesh_build *mb, const scene_material *m)
{
	for (int i = 0; i < mb->m.n_mats; i++)
		if (memcmp(&mb->m.mats[i], m, sizeof *m) == 0)
			return i;
	mb->m.mats = eval_xrealloc(mb->m.mats, (mb->m.n_mats + 1) * sizeof *mb->m.mats);
	mb->m.mats[mb->m.n_mats] = *m;
	return mb->m.n_mats++;
}

static bool degenerate(const double p[3][3])
{
	double a[3], b[3], c[3];
	for (int i = 0; i < 3; i++) {
		a[i] = p[1][i] - p[0][i];
		b[i] = p[2][i] - p[0][i];
	}
	c[0] = a[1] * b[2] - a[2] * b[1];
	c[1] = a[2] * b[0] - a[0] * b[2];
	c[2] = a[0] * b[1] - a[1] * b[0];
	return c[0] * c[0] + c[1] * c[1] + c[2] * c[2] < 1e-20;
}

/* A smooth triangle in a mesh makes every face carry normals: a flat face's are
 * its geometric normal, three times. The same for uv_vectors, whose default is
 * POV-Ray's <0,0> <1,0> <1,1>. */
static void mesh_need_normals(struct mesh_build *mb)
{
	if (mb->m.face_nrm)
		return;
	mb->m.face_nrm = eval_xrealloc(NULL, (mb->cap_f ? mb->cap_f : 1) * sizeof *mb->m.face_nrm);
	for (int f = 0; f < mb->m.n_faces; f++) {
		const double *a = mb->m.v[mb->m.face[f][0]], *b = mb->m.v[mb->m.face[f][1]], *c = mb->m.v[mb->m.face[f][2]];
		double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, w[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
		double n[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0] };
		mesh_normal(mb, n);
		for (int k = 0; k < 3; k++)
			mb->m.face_nrm[f][k] = mb->m.n_nrm - 1;
	}
}

static void mesh_need_uv(struct mesh_build *mb)
{
	static const double def[3][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 } };
	if (mb->m.face_uv)
		return;
	mb->m.face_uv = eval_xrealloc(NULL, (mb->cap_f ? mb->cap_f : 1) * sizeof *mb->m.face_uv);
	for (int k = 0; k < 3; k++)
		mesh_uv(mb, def[k]);
	for (int f = 0; f < mb->m.n_faces; f++)
		for (int k = 0; k < 3; k++)
			mb->m.face_uv[f][k] = k;
}

struct mesh_tri {
	double p[3][3], n[3][3], uv[3][2];
	bool smooth, has_uv, has_mat;
	scene_material mat;
};

static void mesh_add_face(struct mesh_build *mb, const struct mesh_tri *t)
{
	if (t->smooth)
		mesh_need_normals(mb);
	if (t->has_uv)
		mesh_need_uv(mb);
	grow_faces(mb);
	int f = mb->m.n_faces++;
	for (int k = 0; k < 3; k++) {
		mesh_vertex(mb, t->p[k]);
		mb->m.face[f][k] = mb->m.n_v - 1;
	}
	if (mb->m.face_nrm) {
		double u[3], w[3], n[3];
		for (int i = 0; i < 3; i++) {
			u[i] = t->p[1][i] - t->p[0][i];
			w[i] = t->p[2][i] - t->p[0][i];
		}
		n[0] = u[1] * w[2] - u[2] * w[1];
		n[1] = u[2] * w[0] - u[0] * w[2];
		n[2] = u[0] * w[1] - u[1] * w[0];
		for (int k = 0; k < 3; k++) {
			mesh_normal(mb, t->smooth ? t->n[k] : n);
			mb->m.face_nrm[f][k] = mb->m.n_nrm - 1;
		}
	}
	if (mb->m.face_uv) {
		static const double def[3][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 } };
		for (int k = 0; k < 3; k++) {
			mesh_uv(mb, t->has_uv ? t->uv[k] : def[k]);
			mb->m.face_uv[f][k] = mb->m.n_uv - 1;
		}
	}
	mb->m.face_mat[f] = t->has_mat ? mesh_material(mb, &t->mat) : -1;
}

static int uv_arg(struct eval *e, const ast_node *n, double uv[2])
{
	double v[3];
	if (eval_expect_vector(e, n, v))
		return -1;
	uv[0] = v[0];
	uv[1] = v[1];
	return 0;
}

/* The items of a mesh triangle after its corners: [uv_vectors <A>, <B>, <C>] [texture { T }] */
static int mesh_tri_item(struct eval *e, struct cursor *c, const ast_node *item, struct mesh_tri *t)
{
	int err = 0;
	if (item->kind == AST_ARG && item->kw == KW_UV_VECTORS) {
		const ast_node *b = eval_next_expr(c, &err), *d = b ? eval_next_expr(c, &err) : NULL;
		if (!d) {
			eval_error(e, item->loc, "uv_vectors in a mesh triangle needs three uv vectors");
			return -1;
		}
		t->has_uv = true;
		return uv_arg(e, item->kids[0], t->uv[0]) || uv_arg(e, b, t->uv[1]) || uv_arg(e, d, t->uv[2]) ? -1 : 0;
	}
	if (item->kind == AST_BLOCK && item->kw == KW_TEXTURE) {
		value v;
		if (eval_material_value(e, item, &v))
			return -1;
		t->mat = v.mat;
		t->has_mat = true;
		return 0;
	}
	return eval_not_valid(e, item, "a mesh triangle");
}

/* triangle { <A>, <B>, <C> [MESH_TRIANGLE_ITEMS] } or smooth_triangle { ... } in a mesh */
static int mesh_triangle(struct eval *e, const ast_node *b, struct mesh_build *mb)
{
	struct mesh_tri t = { .smooth = b->kw == KW_SMOOTH_TRIANGLE };
	scene_object o = { 0 };
	struct cursor c;
	int err = 0;
	eval_cursor_init(&c, e, b);
	int rc = arguments(e, &c, b, t.smooth ? &shape_smooth_triangle : &shape_triangle, &o);
	for (int k = 0; rc == 0 && k < 3; k++) {
		memcpy(t.p[k], o.p[k], sizeof t.p[k]);
		memcpy(t.n[k], o.n[k], sizeof t.n[k]);
	}
	const ast_node *item;
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL)
		rc = mesh_tri_item(e, &c, item, &t);
	eval_cursor_free(&c);
	if (rc || err)
		return -1;
	if (!degenerate(t.p))   /* POV-Ray leaves degenerate mesh triangles out, silently */
		mesh_add_face(mb, &t);
	return 0;
}

static int inside_vector(struct eval *e, const ast_node *item, scene_mesh *m)
{
	double v[3];
	if (eval_expect_vector(e, item->kids[0], v))
		return -1;
	double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
	m->has_inside_vector = l > 1e-10;
	for (int i = 0; i < 3; i++)
		m->inside_vector[i] = l > 1e-10 ? v[i] / l : 0;
	return 0;
}

static void mesh_build_free(struct mesh_build *mb)
{
	free(mb->m.v);
	free(mb->m.nrm);
	free(mb->m.uv);
	free(mb->m.face);
	free(mb->m.face_nrm);
	free(mb->m.face_uv);
	free(mb->m.face_mat);
	free(mb->m.mats);
}

/* Stores the mesh in the scene once; the object refers to it. */
static int mesh_object(struct eval *e, const ast_node *b, struct mesh_build *mb, struct cursor *c, value *out)
{
	if (mb->m.n_faces == 0) {
		eval_error(e, b->loc, "%s has no triangles", ast_keyword_name(b->kw));
		mesh_build_free(mb);
		return -1;
	}
	bool any_mat = false;
	for (int f = 0; f < mb->m.n_faces; f++)
		any_mat |= mb->m.face_mat[f] >= 0;
	if (!any_mat) {
		free(mb->m.face_mat);
		mb->m.face_mat = NULL;
	}
	mb->m.loc = b->loc;
	scene_object o = new_object(e, SHAPE_MESH, b->loc);
	o.mesh = scene_add_mesh(e->s, &mb->m);
	*out = (value){ .kind = V_OBJECT, .obj = eval_objval_new(b->loc) };
	eval_objval_add(out->obj, &o);
	char a[40];
	int rc = modifiers(e, c, out->obj, with_article(ast_keyword_name(b->kw), a, sizeof a));
	if (rc)
		eval_value_free(out);
	return rc;
}

/* The folder of the file that holds loc, joined to name when name is relative. */
static char *beside_source(src_loc loc, const char *name)
{
	const char *from = diag_source_name(loc.file), *slash = strrchr(from, '/');
	size_t n = strlen(name) + (slash ? (size_t)(slash - from) + 1 : 0) + 1;
	char *path = eval_xrealloc(NULL, n);
	if (name[0] == '/' || !slash)
		snprintf(path, n, "%s", name);
	else
		snprintf(path, n, "%.*s/%s", (int)(slash - from), from, name);
	return path;
}

/* file "NAME" in a mesh, an eclat extension: the triangles of a mesh file (OBJ,
 * PLY, STL, OFF, glTF and the other formats assimp reads), NAME relative to the
 * folder of the scene file that says it. POV-Ray skips it inside
 * #ifdef (eclat_version).
 *
 * 'file' is no keyword: POV-Ray reserves no such word and its scenes use it as an
 * identifier. It is a word of its own only as an item right inside a mesh, where
 * POV-Ray accepts no bare identifier; the parser reads it as an identifier (or
 * as a call, for file ("NAME")) and the name as the next item. */
static bool is_file_word(const ast_node *item)
{
	return (item->kind == AST_IDENT || (item->kind == AST_CALL && item->n_kids == 1)) &&
	       strcmp(item->str, AST_WORD_MESH_FILE) == 0;
}

static int mesh_file(struct eval *e, struct cursor *c, const ast_node *item, struct mesh_build *mb)
{
	char *name, err[512];
	int bad = 0;
	const ast_node *arg = item->kind == AST_CALL ? item->kids[0] : eval_next_expr(c, &bad);
	if (!arg) {
		if (!bad)
			eval_error(e, item->loc, "'file' needs the name of a mesh file after it");
		return -1;
	}
	if (eval_expect_string(e, arg, &name))
		return -1;
	if (mb->m.n_faces > 0) {
		eval_error(e, item->loc, "a mesh takes its triangles from a file or from triangle blocks, not both");
		free(name);
		return -1;
	}
	char *path = beside_source(arg->loc, name);
	free(name);
	scene_mesh m;
	int rc = eval_access(e, path, false, arg->loc, "a mesh");
	/* checked with the counts the child sends, before they are allocated */
	if (rc == 0 && (rc = mesh_io_load_cached(e->opt->mesh_cache, path, e->opt->mesh_time_limit,
	                                             eval_memory_left(e), &m, err, sizeof err)) != 0)
		eval_error(e, arg->loc, "cannot load the mesh '%s': %s", path, err);
	free(path);
	if (rc)
		return -1;
	if (eval_memory_claim(e, arg->loc, mesh_io_bytes(m.n_v, m.n_faces, m.nrm != NULL), "the mesh")) {
		scene_mesh_free(&m);
		return -1;
	}
	m.face_mat = eval_xrealloc(NULL, (m.n_faces ? m.n_faces : 1) * sizeof *m.face_mat);
	for (int f = 0; f < m.n_faces; f++)
		m.face_mat[f] = -1;   /* every face takes the mesh's texture */
	mesh_build_free(mb);
	*mb = (struct mesh_build){ .m = m, .cap_v = m.n_v, .cap_f = m.n_faces, .cap_nrm = m.n_nrm,
	                           .smooth = m.nrm != NULL };
	return 0;
}

/* mesh { TRIANGLE... [inside_vector <V>] [OBJECT_MODIFIERS...] }
 * mesh { file "NAME" [inside_vector <V>] [OBJECT_MODIFIERS...] }   (eclat) */
/* mesh { MESH_IDENTIFIER [OBJECT_MODIFIERS...] } (and mesh2's): a copy of a
 * declared mesh, as POV-Ray's Parse_Object_Id allows. 1 when b does not start
 * with an identifier of an object. */
static int declared_mesh(struct eval *e, const ast_node *b, struct cursor *c, value *out)
{
	int err = 0;
	const ast_node *first = eval_next(c, &err);
	if (err)
		return -1;
	const value *v = first && first->kind == AST_IDENT ? eval_lookup(e, first->str) : NULL;
	if (!v || v->kind != V_OBJECT) {
		if (first)
			eval_unget(c, first);
		return 1;
	}
	if (v->obj->n_objs != 1 || v->obj->n_lights || v->obj->objs[0].shape != SHAPE_MESH) {
		eval_error(e, first->loc, "'%s' is not a mesh", first->str);
		return -1;
	}
	if (eval_expr(e, first, out))
		return -1;
	char a[40];
	int rc = modifiers(e, c, out->obj, with_article(ast_keyword_name(b->kw), a, sizeof a));
	if (rc)
		eval_value_free(out);
	return rc;
}

static int mesh(struct eval *e, const ast_node *b, value *out)
{
	struct mesh_build mb = { 0 };
	struct cursor c;
	int err = 0, rc = 0;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	if ((rc = declared_mesh(e, b, &c, out)) <= 0) {
		eval_cursor_free(&c);
		return rc;
	}
	rc = 0;
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		if (item->kind == AST_BLOCK && (item->kw == KW_TRIANGLE || item->kw == KW_SMOOTH_TRIANGLE))
			rc = mesh_triangle(e, item, &mb);
		else if (item->kind == AST_ARG && item->kw == KW_INSIDE_VECTOR)
			rc = inside_vector(e, item, &mb.m);
		else if (is_file_word(item))
			rc = mesh_file(e, &c, item, &mb);
		else {
			eval_unget(&c, item);
			break;
		}
	}
	if (rc || err) {
		mesh_build_free(&mb);
		eval_cursor_free(&c);
		return -1;
	}
	rc = mesh_object(e, b, &mb, &c, out);
	eval_cursor_free(&c);
	return rc;
}

/* ---- mesh2 ---- */

/* NAME { Count, Items... }: the count, and the values of the items after it. */
static int counted(struct eval *e, const ast_node *b, value **vals, const ast_node ***at, int *n)
{
	struct cursor c;
	int err = 0, count = 0, cap = 0, rc = 0;
	const ast_node *item;
	*vals = NULL;
	*at = NULL;
	*n = 0;
	eval_cursor_init(&c, e, b);
	const ast_node *first = eval_next_expr(&c, &err);
	if (!first || eval_expect_int(e, first, &count) || count < 0) {
		if (!err && (!first || count < 0))
			eval_error(e, first ? first->loc : b->loc, "%s needs a count first", ast_keyword_name(b->kw));
		eval_cursor_free(&c);
		return -1;
	}
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		if (!AST_IS_EXPRESSION(item->kind)) {
			rc = eval_not_valid(e, item, ast_keyword_name(b->kw));
			break;
		}
		if (*n == cap) {
			cap = cap ? 2 * cap : 64;
			*vals = eval_xrealloc(*vals, cap * sizeof **vals);
			*at = eval_xrealloc(*at, cap * sizeof **at);
		}
		(*at)[*n] = item;
		rc = eval_expr(e, item, &(*vals)[*n]);
		*n += rc == 0;
	}
	eval_cursor_free(&c);
	if (rc || err) {
		for (int i = 0; i < *n; i++)
			eval_value_free(&(*vals)[i]);
		free(*vals);
		free(*at);
		return -1;
	}
	return count;
}

static void free_values(value *vals, const ast_node **at, int n)
{
	for (int i = 0; i < n; i++)
		eval_value_free(&vals[i]);
	free(vals);
	free(at);
}

/* A value that must be a vector of 3 components, or a float (which fills it). */
static int as_vector(struct eval *e, const ast_node *at, const value *v, double out[3])
{
	if (v->kind != V_FLOAT && !(v->kind == V_VECTOR && v->n <= 3)) {
		eval_error(e, at->loc, "expected a vector, found %s", eval_kind_name(v->kind));
		return -1;
	}
	double w[5];
	eval_widen(v, 3, w);
	memcpy(out, w, 3 * sizeof *out);
	return 0;
}

/* vertex_vectors { N, <V>... }, normal_vectors (normalized), uv_vectors. */
static int vectors_block(struct eval *e, const ast_node *b, double (**out)[3], int *n, bool normalize)
{
	value *vals;
	const ast_node **at;
	int got, count = counted(e, b, &vals, &at, &got), rc = 0;
	if (count < 0)
		return -1;
	if (got != count) {
		eval_error(e, b->loc, "%s says %d, and has %d", ast_keyword_name(b->kw), count, got);
		free_values(vals, at, got);
		return -1;
	}
	*out = eval_xrealloc(*out, (size_t)(count ? count : 1) * sizeof **out);
	*n = count;
	for (int i = 0; rc == 0 && i < count; i++) {
		double *v = (*out)[i];
		if ((rc = as_vector(e, at[i], &vals[i], v)) != 0)
			break;
		double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
		if (normalize && l < 1e-10) {
			eval_warning(e, at[i]->loc, "a normal of length 0 changed to <1, 0, 0>, as POV-Ray does");
			v[0] = 1, v[1] = v[2] = 0, l = 1;
		}
		for (int k = 0; normalize && k < 3; k++)
			v[k] /= l;
	}
	free_values(vals, at, got);
	return rc;
}

/* One face: <A, B, C>, each index in 0 to limit - 1. */
static int face(struct eval *e, const ast_node *at, const value *v, int limit, int out[3])
{
	double w[3];
	if (v->kind != V_VECTOR || as_vector(e, at, v, w)) {
		if (v->kind != V_VECTOR)
			eval_error(e, at->loc, "expected a vector of indices <A, B, C>, found %s", eval_kind_name(v->kind));
		return -1;
	}
	for (int k = 0; k < 3; k++) {
		if (!(w[k] >= 0 && w[k] < limit)) {
			eval_error(e, at->loc, "index %g is out of the range 0 to %d", w[k], limit - 1);
			return -1;
		}
		out[k] = (int)w[k];
	}
	return 0;
}

/* face_indices { N, <A, B, C> [, Texture [, T2, T3]]... }, normal_indices, uv_indices:
 * a face's texture is the first index after it (three give a gradient in POV-Ray). */
static int indices_block(struct eval *e, const ast_node *b, int (**faces)[3], int **mats, int *n, int limit,
                         int n_mats)
{
	value *vals;
	const ast_node **at;
	int got, count = counted(e, b, &vals, &at, &got), f = 0, rc = 0;
	if (count < 0)
		return -1;
	*faces = eval_xrealloc(NULL, (size_t)(count ? count : 1) * sizeof **faces);
	if (mats)
		*mats = eval_xrealloc(NULL, (size_t)(count ? count : 1) * sizeof **mats);
	for (int i = 0; rc == 0 && i < got; f++) {
		if (f >= count) {
			eval_error(e, at[i]->loc, "%s says %d, and has more", ast_keyword_name(b->kw), count);
			rc = -1;
			break;
		}
		rc = face(e, at[i], &vals[i], limit, (*faces)[f]);
		i++;
		if (mats)
			(*mats)[f] = -1;
		for (int t = 0; rc == 0 && mats && t < 3 && i < got && vals[i].kind == V_FLOAT; t++, i++) {
			double ti = vals[i].v[0];
			if (!(ti >= 0 && ti < n_mats)) {
				eval_error(e, at[i]->loc, "texture index %g is out of the range of the texture_list", ti);
				rc = -1;
			} else if (t == 0) {
				(*mats)[f] = (int)ti;
			}
		}
	}
	if (rc == 0 && f != count) {
		eval_error(e, b->loc, "%s says %d, and has %d", ast_keyword_name(b->kw), count, f);
		rc = -1;
	}
	free_values(vals, at, got);
	*n = count;
	return rc;
}

/* texture_list { N, texture { ... }... } */
static int texture_list(struct eval *e, const ast_node *b, scene_mesh *m)
{
	struct cursor c;
	int err = 0, count, rc = 0;
	eval_cursor_init(&c, e, b);
	const ast_node *first = eval_next_expr(&c, &err), *item;
	if (!first || eval_expect_int(e, first, &count) || count < 0) {
		if (!first && !err)
			eval_error(e, b->loc, "texture_list needs a count first");
		eval_cursor_free(&c);
		return -1;
	}
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL) {
		value v;
		if (item->kind != AST_BLOCK || item->kw != KW_TEXTURE)
			rc = eval_not_valid(e, item, "a texture_list");
		else if ((rc = eval_material_value(e, item, &v)) == 0) {
			m->mats = eval_xrealloc(m->mats, (m->n_mats + 1) * sizeof *m->mats);
			m->mats[m->n_mats++] = v.mat;
		}
	}
	eval_cursor_free(&c);
	if (rc == 0 && !err && m->n_mats != count) {
		eval_error(e, b->loc, "texture_list says %d, and has %d", count, m->n_mats);
		rc = -1;
	}
	return rc || err ? -1 : 0;
}

struct mesh2_parts {
	const ast_node *faces, *normal_indices, *uv_indices;
	int n_nrm_idx, n_uv_idx;
};

/* The index blocks are read where they are, in POV-Ray's order after the
 * vectors and textures they index: a block that comes from an #include or a
 * macro may use its #locals, which end with it. */
static int mesh2_indices(struct eval *e, const ast_node *item, scene_mesh *m, struct mesh2_parts *p)
{
	if (item->kind != AST_BLOCK)
		return eval_not_valid(e, item, "a mesh2");
	const ast_node *had = item->kw == KW_FACE_INDICES ? p->faces
	                    : item->kw == KW_NORMAL_INDICES ? p->normal_indices : p->uv_indices;
	if (had) {
		eval_error(e, item->loc, "a mesh2 has one %s", ast_keyword_name(item->kw));
		return -1;
	}
	if (item->kw == KW_FACE_INDICES) {
		if (m->n_v == 0) {
			eval_error(e, item->loc, "mesh2 needs vertex_vectors before face_indices");
			return -1;
		}
		p->faces = item;
		return indices_block(e, item, &m->face, &m->face_mat, &m->n_faces, m->n_v, m->n_mats);
	}
	if (item->kw == KW_NORMAL_INDICES) {
		p->normal_indices = item;
		return indices_block(e, item, &m->face_nrm, NULL, &p->n_nrm_idx, m->n_nrm, 0);
	}
	p->uv_indices = item;
	return indices_block(e, item, &m->face_uv, NULL, &p->n_uv_idx, m->n_uv, 0);
}

static int mesh2_item(struct eval *e, const ast_node *item, scene_mesh *m, struct mesh2_parts *p)
{
	switch (item->kind == AST_BLOCK || item->kind == AST_ARG ? item->kw : -1) {
	case KW_VERTEX_VECTORS: return vectors_block(e, item, &m->v, &m->n_v, false);
	case KW_NORMAL_VECTORS: return vectors_block(e, item, &m->nrm, &m->n_nrm, true);
	case KW_UV_VECTORS: {
		double (*v)[3] = NULL;
		if (item->kind != AST_BLOCK || vectors_block(e, item, &v, &m->n_uv, false))
			return item->kind != AST_BLOCK ? eval_not_valid(e, item, "a mesh2") : -1;
		m->uv = eval_xrealloc(m->uv, (size_t)(m->n_uv ? m->n_uv : 1) * sizeof *m->uv);
		for (int i = 0; i < m->n_uv; i++)
			m->uv[i][0] = v[i][0], m->uv[i][1] = v[i][1];
		free(v);
		return 0;
	}
	case KW_TEXTURE_LIST: return texture_list(e, item, m);
	case KW_FACE_INDICES: case KW_NORMAL_INDICES: case KW_UV_INDICES: return mesh2_indices(e, item, m, p);
	case KW_INSIDE_VECTOR: return inside_vector(e, item, m);
	default: return 1;
	}
}

/* The index blocks agree with each other. */
static int mesh2_faces(struct eval *e, const ast_node *b, scene_mesh *m, const struct mesh2_parts *p)
{
	if (!p->faces) {
		eval_error(e, b->loc, "mesh2 needs face_indices");
		return -1;
	}
	if (p->normal_indices && p->n_nrm_idx != m->n_faces) {
		eval_error(e, p->normal_indices->loc, "normal_indices has %d, face_indices %d", p->n_nrm_idx, m->n_faces);
		return -1;
	}
	if (p->uv_indices && p->n_uv_idx != m->n_faces) {
		eval_error(e, p->uv_indices->loc, "uv_indices has %d, face_indices %d", p->n_uv_idx, m->n_faces);
		return -1;
	}
	return 0;
}

/* Without normal_indices (uv_indices) the face indices index the normals (uvs),
 * as in POV-Ray: there must be one per vertex then. */
static int mesh2_defaults(struct eval *e, const ast_node *b, scene_mesh *m)
{
	if (m->n_nrm && !m->face_nrm) {
		if (m->n_nrm != m->n_v) {
			eval_error(e, b->loc, "mesh2 without normal_indices needs one normal per vertex");
			return -1;
		}
		m->face_nrm = eval_xrealloc(NULL, m->n_faces * sizeof *m->face_nrm);
		memcpy(m->face_nrm, m->face, m->n_faces * sizeof *m->face_nrm);
	}
	if (m->n_uv && !m->face_uv && m->n_uv == m->n_v) {
		m->face_uv = eval_xrealloc(NULL, m->n_faces * sizeof *m->face_uv);
		memcpy(m->face_uv, m->face, m->n_faces * sizeof *m->face_uv);
	}
	return 0;
}

/* mesh2 { vertex_vectors {...} [normal_vectors {...}] [uv_vectors {...}]
 *         [texture_list {...}] face_indices {...} [normal_indices {...}]
 *         [uv_indices {...}] [inside_vector <V>] [OBJECT_MODIFIERS...] } */
static int mesh2(struct eval *e, const ast_node *b, value *out)
{
	struct mesh_build mb = { 0 };
	struct mesh2_parts p = { 0 };
	struct cursor c;
	int err = 0, rc = 0;
	const ast_node *item;
	eval_cursor_init(&c, e, b);
	if ((rc = declared_mesh(e, b, &c, out)) <= 0) {
		eval_cursor_free(&c);
		return rc;
	}
	rc = 0;
	while (rc == 0 && (item = eval_next(&c, &err)) != NULL)
		if ((rc = mesh2_item(e, item, &mb.m, &p)) > 0) {
			eval_unget(&c, item);
			rc = 0;
			break;
		}
	if (rc == 0 && !err)
		rc = mesh2_faces(e, b, &mb.m, &p) || mesh2_defaults(e, b, &mb.m) ? -1 : 0;
	if (rc || err) {
		mesh_build_free(&mb);
		eval_cursor_free(&c);
		return -1;
	}
	rc = mesh_object(e, b, &mb, &c, out);
	eval_cursor_free(&c);
	return rc;
}

/* ---- any object ---- */

bool eval_is_object_block(const ast_node *b)
{
	if (b->kind != AST_BLOCK)
		return false;
	switch (b->kw) {
	case KW_MESH: case KW_MESH2: case KW_UNION: case KW_OBJECT: case KW_LIGHT_SOURCE:
	case KW_MERGE: case KW_INTERSECTION: case KW_DIFFERENCE:
		return true;
	case KW_UNKNOWN: {
		const char *w = eval_pov_word(b->str);
		return shape_named(b->str, NULL) || (w && strcmp(w, "object") == 0);
	}
	default:
		return shape_named(ast_keyword_name(b->kw), NULL) != NULL;
	}
}

/* An object eclat cannot render: kept as a placeholder, an error (or, with
 * skip_unsupported, a warning) when it is put into the scene. */
static int unsupported(struct eval *e, const ast_node *b, value *out)
{
	(void)e;
	*out = (value){ .kind = V_OBJECT, .obj = eval_objval_new(b->loc) };
	out->obj->unsupported = b->str;
	out->obj->unsupported_loc = b->loc;
	return 0;
}

int eval_object(struct eval *e, const ast_node *b, value *out)
{
	switch (b->kw) {
	case KW_UNION: return union_block(e, b, out);
	case KW_OBJECT: return object_statement(e, b, out);
	case KW_MESH: return mesh(e, b, out);
	case KW_MESH2: return mesh2(e, b, out);
	case KW_LIGHT_SOURCE: return eval_light(e, b, out);
	case KW_MERGE: case KW_INTERSECTION: case KW_DIFFERENCE: return csg_block(e, b, out);
	default:
		return shape_named(block_name(b), NULL) ? shape(e, b, out) : unsupported(e, b, out);
	}
}

/* Puts an object (and the lights in it) into the scene. */
void eval_place(struct eval *e, value *v)
{
	struct objval *o = v->obj;
	resolve_texture(o);
	if (o->unsupported) {
		if (!e->opt->skip_unsupported) {
			eval_error(e, o->unsupported_loc, "'%s' is not supported yet", o->unsupported);
			return;
		}
		eval_warning(e, o->unsupported_loc, "'%s' is not supported yet; left out", o->unsupported);
	}
	for (int i = 0; i < o->n_lights; i++) {
		struct lightval *l = &o->lights[i];
		l->light.looks_like = l->n_looks ? e->s->n_objects : -1;
		for (int k = 0; k < l->n_looks; k++) {
			l->looks[k].flags |= OBJ_NO_SHADOW;
			l->looks[k].csg = 0;   /* a looks_like's CSG is drawn as its shapes alone */
			scene_add_object(e->s, &l->looks[k]);
		}
		scene_add_light(e->s, &l->light);
	}
	int first = e->s->n_objects;
	if (o->n_objs == 1 && o->n_csgs == 0)
		eval_poly_bound(e, &o->objs[0], o->bound);
	for (int i = 0; i < o->n_objs; i++) {
		o->objs[i].csg = 0;
		if (!o->objs[i].textured)   /* POV-Ray's Post_Process: the default when it is placed */
			take_texture(&o->objs[i].material, &e->default_mat);
		scene_add_object(e->s, &o->objs[i]);
	}
	for (int i = 0; i < o->n_csgs; i++) {
		struct objcsg *g = &o->csgs[i];
		int id = scene_add_csg(e->s, &(scene_csg){ .first = first + g->first, .n_leaves = g->n_leaves,
		                                           .ops = g->ops, .n_ops = g->n_ops, .loc = g->loc });
		g->ops = NULL;
		for (int k = 0; k < g->n_leaves; k++)
			e->s->objects[first + g->first + k].csg = id + 1;
	}
}

/* The object of an object pattern, item (an object or an object identifier:
 * POV-Ray's Parse_Bound_Clip there, which takes one): put into the scene as a
 * CSG object flagged pattern, the union of its parts, whose leaves no ray
 * meets; only the pattern asks its inside (POV-Ray's Inside_Object). Its
 * index in scene.csgs in *csg, or -1 after an error. */
int eval_pattern_object(struct eval *e, const ast_node *item, int *csg)
{
	value v = { .kind = V_NONE };
	int rc = -1;
	*csg = -1;
	if (AST_IS_EXPRESSION(item->kind)) {
		rc = eval_expr(e, item, &v);
		if (rc == 0 && v.kind != V_OBJECT) {
			eval_error(e, item->loc, "an object pattern needs an object, found %s", eval_kind_name(v.kind));
			rc = -1;
		}
	} else if (eval_is_object_block(item)) {
		rc = eval_object(e, item, &v);
	} else {
		rc = eval_not_valid(e, item, "an object pattern (expected an object or an object identifier first)");
	}
	if (rc == 0 && v.obj->unsupported && !e->opt->skip_unsupported) {
		eval_error(e, v.obj->unsupported_loc, "'%s' is not supported yet", v.obj->unsupported);
		rc = -1;
	} else if (rc == 0 && v.obj->unsupported) {
		eval_warning(e, v.obj->unsupported_loc, "'%s' is not supported yet; the object pattern leaves it out",
		             v.obj->unsupported);
	}
	if (rc) {
		eval_value_free(&v);
		return -1;
	}
	struct objval *o = v.obj;
	csg_prog p = { 0 };
	csg_formula(o, &p, 0);
	int first = e->s->n_objects;
	scene_material plain = scene_default_material();   /* never shaded */
	for (int i = 0; i < o->n_objs; i++) {
		o->objs[i].csg = 0;
		o->objs[i].pattern = true;
		o->objs[i].material = plain;
		scene_add_object(e->s, &o->objs[i]);
	}
	*csg = scene_add_csg(e->s, &(scene_csg){ .first = first, .n_leaves = o->n_objs, .ops = p.ops, .n_ops = p.n,
	                                         .pattern = true, .loc = item->loc });
	for (int k = 0; k < o->n_objs; k++)
		e->s->objects[first + k].csg = *csg + 1;
	eval_value_free(&v);
	return 0;
}

/* The objects of a looks_like { OBJECT }: moved to the light, as POV-Ray does. */
int eval_looks_like(struct eval *e, const ast_node *b, const double at[3], struct lightval *l)
{
	struct cursor c;
	int err = 0;
	eval_cursor_init(&c, e, b);
	const ast_node *item = eval_next(&c, &err);
	value v = { .kind = V_NONE };
	int rc = -1;
	if (item && eval_is_object_block(item))
		rc = eval_object(e, item, &v);
	else if (item && AST_IS_EXPRESSION(item->kind))
		rc = eval_expr(e, item, &v) || v.kind != V_OBJECT ? eval_not_valid(e, item, "looks_like") : 0;
	else if (!err)
		eval_error(e, item ? item->loc : b->loc, "looks_like needs an object");
	if (rc == 0 && (item = eval_next(&c, &err)) != NULL)
		rc = eval_not_valid(e, item, "looks_like (one object)");
	eval_cursor_free(&c);
	if (rc || err) {
		eval_value_free(&v);
		return -1;
	}
	resolve_texture(v.obj);
	xform t = scene_xform_translate(at);
	transform_objval(v.obj, &t);
	free(l->looks);
	l->looks = v.obj->objs;
	l->n_looks = v.obj->n_objs;
	v.obj->objs = NULL;
	v.obj->n_objs = v.obj->cap_objs = 0;
	eval_value_free(&v);
	return 0;
}

/* Transformations of a light: the same as for an object. */
void eval_transform_light(struct lightval *l, const xform *t)
{
	transform_light(l, t);
}
