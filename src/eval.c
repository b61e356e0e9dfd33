/* eval.c: walks the syntax tree in file order, as POV-Ray's parser does, giving
 * every expression a typed value and every block its meaning. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval.h"
#include "parse.h"

typedef enum {
	V_FLOAT, V_VECTOR, V_COLOR, V_STRING, V_OBJECT, V_PIGMENT, V_FINISH, V_TEXTURE
} val_kind;

/* A value of the language. Pigments, finishes and textures share scene_material:
 * a pigment uses its pigment part, a finish the rest, a texture all of it. */
typedef struct {
	val_kind kind;
	int n;              /* components of a vector (2 to 5); colours have 5 */
	double v[5];        /* a float is v[0] */
	char *str;
	scene_object *objs; /* an object: the shapes it is made of */
	int n_objs;
	int compound;       /* an object made by union: mat is its own texture */
	int has_mat;        /* the union has a texture, for its parts without one */
	scene_material mat;
} value;

struct symbol {
	char *name;
	value val;
	struct symbol *next;
};

struct eval {
	scene *s;
	struct symbol *symbols;
	int include_depth;
};

#define MAX_INCLUDE_DEPTH 64

static const char *kind_name(val_kind k)
{
	static const char *const names[] = { /* ORDER val_kind */
		"a float", "a vector", "a colour", "a string", "an object", "a pigment",
		"a finish", "a texture",
	};
	return names[k];
}

static void value_free(value *v)
{
	free(v->str);
	free(v->objs);
	v->str = NULL;
	v->objs = NULL;
}

static value value_copy(const value *v)
{
	value c = *v;
	c.str = v->str ? strdup(v->str) : NULL;
	if (v->n_objs) {
		c.objs = malloc(v->n_objs * sizeof *c.objs);
		if (!c.objs) {
			fprintf(stderr, "eclat: out of memory\n");
			exit(1);
		}
		memcpy(c.objs, v->objs, v->n_objs * sizeof *c.objs);
	}
	return c;
}

static void add_object(value *v, const scene_object *o)
{
	scene_object *objs = realloc(v->objs, (v->n_objs + 1) * sizeof *objs);
	if (!objs) {
		fprintf(stderr, "eclat: out of memory\n");
		exit(1);
	}
	v->objs = objs;
	v->objs[v->n_objs++] = *o;
}

/* ---- symbols ---- */

static struct symbol *lookup(struct eval *e, const char *name)
{
	for (struct symbol *s = e->symbols; s; s = s->next)
		if (strcmp(s->name, name) == 0)
			return s;
	return NULL;
}

static void declare(struct eval *e, const char *name, value v)
{
	struct symbol *s = lookup(e, name);
	if (s) {
		value_free(&s->val);
		s->val = v;
		return;
	}
	s = malloc(sizeof *s);
	if (!s || !(s->name = strdup(name))) {
		fprintf(stderr, "eclat: out of memory\n");
		exit(1);
	}
	s->val = v;
	s->next = e->symbols;
	e->symbols = s;
}

static void declare_vector(struct eval *e, const char *name, double a, double b, double c)
{
	declare(e, name, (value){ .kind = V_VECTOR, .n = 3, .v = { a, b, c } });
}

static void declare_float(struct eval *e, const char *name, double f)
{
	declare(e, name, (value){ .kind = V_FLOAT, .v = { f } });
}

/* POV-Ray's predeclared identifiers, and eclat_version so a scene can test for eclat. */
static void declare_builtins(struct eval *e)
{
	declare_vector(e, "x", 1, 0, 0);
	declare_vector(e, "y", 0, 1, 0);
	declare_vector(e, "z", 0, 0, 1);
	declare_float(e, "pi", M_PI);
	static const char *const yes[] = { "true", "yes", "on" }, *const no[] = { "false", "no", "off" };
	for (int i = 0; i < 3; i++) {
		declare_float(e, yes[i], 1);
		declare_float(e, no[i], 0);
	}
	declare_float(e, "eclat_version", strtod(PACKAGE_VERSION, NULL));
}

/* ---- expressions ---- */

static int eval_expr(struct eval *e, const ast_node *n, value *out);

/* Promotes a float or vector to a vector of n components (a float fills them all). */
static void widen(const value *v, int n, double out[5])
{
	for (int i = 0; i < 5; i++)
		out[i] = v->kind == V_FLOAT ? (i < n ? v->v[0] : 0) : (i < v->n ? v->v[i] : 0);
}

static int is_numeric(val_kind k)
{
	return k == V_FLOAT || k == V_VECTOR || k == V_COLOR;
}

static int eval_binary(struct eval *e, const ast_node *n, value *out)
{
	value a, b;
	if (eval_expr(e, n->kids[0], &a) || eval_expr(e, n->kids[1], &b))
		return -1;
	if (!is_numeric(a.kind) || !is_numeric(b.kind)) {
		diag_error(n->loc, "cannot apply '%c' to %s and %s", n->op, kind_name(a.kind), kind_name(b.kind));
		value_free(&a);
		value_free(&b);
		return -1;
	}
	int size = a.kind == V_FLOAT ? b.n : b.kind == V_FLOAT ? a.n : (a.n > b.n ? a.n : b.n);
	*out = (value){ .kind = a.kind == V_COLOR || b.kind == V_COLOR ? V_COLOR
	                       : a.kind == V_FLOAT && b.kind == V_FLOAT ? V_FLOAT : V_VECTOR,
	                .n = size ? size : 1 };
	double x[5], y[5];
	widen(&a, 5, x);
	widen(&b, 5, y);
	for (int i = 0; i < 5; i++) {
		if (n->op == '/' && y[i] == 0 && i < out->n) {
			diag_error(n->loc, "division by zero");
			return -1;
		}
		out->v[i] = n->op == '+' ? x[i] + y[i] : n->op == '-' ? x[i] - y[i]
		          : n->op == '*' ? x[i] * y[i] : (y[i] != 0 ? x[i] / y[i] : 0);
	}
	return 0;
}

static int eval_vector(struct eval *e, const ast_node *n, value *out)
{
	if (n->n_kids < 2 || n->n_kids > 5) {
		diag_error(n->loc, "a vector has 2 to 5 components, this one has %d", n->n_kids);
		return -1;
	}
	*out = (value){ .kind = V_VECTOR, .n = n->n_kids };
	for (int i = 0; i < n->n_kids; i++) {
		value c;
		if (eval_expr(e, n->kids[i], &c))
			return -1;
		if (c.kind != V_FLOAT) {
			diag_error(n->kids[i]->loc, "expected a float as vector component, found %s", kind_name(c.kind));
			value_free(&c);
			return -1;
		}
		out->v[i] = c.v[0];
	}
	return 0;
}

/* rgb, rgbf, rgbt and rgbft take 3, 4, 4 and 5 numbers; color takes any colour. */
static int eval_color(struct eval *e, const ast_node *n, value *out)
{
	value a;
	if (eval_expr(e, n->kids[0], &a))
		return -1;
	if (!is_numeric(a.kind)) {
		diag_error(n->kids[0]->loc, "expected a colour after '%s', found %s", ast_keyword_name(n->kw), kind_name(a.kind));
		value_free(&a);
		return -1;
	}
	*out = (value){ .kind = V_COLOR, .n = 5 };
	if (n->kw == KW_COLOR || n->kw == KW_COLOUR) {
		widen(&a, 5, out->v);   /* POV-Ray: "color 0.5" sets filter and transmit too */
		return 0;
	}
	static const int slots[][5] = {   /* which colour component each number fills */
		[KW_RGB] = { 0, 1, 2, -1, -1 }, [KW_RGBF] = { 0, 1, 2, 3, -1 },
		[KW_RGBT] = { 0, 1, 2, 4, -1 }, [KW_RGBFT] = { 0, 1, 2, 3, 4 },
	};
	int want = n->kw == KW_RGB ? 3 : n->kw == KW_RGBFT ? 5 : 4;
	if (a.kind == V_COLOR) {   /* rgb C keeps the components rgb names, as POV-Ray does */
		for (int i = 0; i < want; i++)
			out->v[slots[n->kw][i]] = a.v[slots[n->kw][i]];
		return 0;
	}
	if (a.kind != V_FLOAT && a.n != want) {
		diag_error(n->kids[0]->loc, "'%s' takes a vector of %d components, found %d",
		           ast_keyword_name(n->kw), want, a.n);
		return -1;
	}
	double w[5];
	widen(&a, want, w);
	for (int i = 0; i < want; i++)
		out->v[slots[n->kw][i]] = w[i];
	return 0;
}

static int eval_expr(struct eval *e, const ast_node *n, value *out)
{
	switch (n->kind) {
	case AST_NUMBER:
		*out = (value){ .kind = V_FLOAT, .v = { n->num } };
		return 0;
	case AST_STRING:
		*out = (value){ .kind = V_STRING, .str = strdup(n->str) };
		return 0;
	case AST_IDENT: {
		struct symbol *s = lookup(e, n->str);
		if (!s) {
			diag_error(n->loc, "undeclared identifier '%s'", n->str);
			return -1;
		}
		*out = value_copy(&s->val);
		return 0;
	}
	case AST_VECTOR:
		return eval_vector(e, n, out);
	case AST_BINARY:
		return eval_binary(e, n, out);
	case AST_UNARY:
		if (eval_expr(e, n->kids[0], out))
			return -1;
		if (!is_numeric(out->kind)) {
			diag_error(n->loc, "cannot apply '%c' to %s", n->op, kind_name(out->kind));
			value_free(out);
			return -1;
		}
		for (int i = 0; i < 5 && n->op == '-'; i++)
			out->v[i] = -out->v[i];
		return 0;
	case AST_COLOR:
		return eval_color(e, n, out);
	default:
		diag_error(n->loc, "expected an expression, found '%s'", ast_keyword_name(n->kw));
		return -1;
	}
}

/* Evaluates n and checks its type; floats promote to vectors and colours. */
static int expect_float(struct eval *e, const ast_node *n, double *f)
{
	value v;
	if (eval_expr(e, n, &v))
		return -1;
	if (v.kind != V_FLOAT) {
		diag_error(n->loc, "expected a float, found %s", kind_name(v.kind));
		value_free(&v);
		return -1;
	}
	*f = v.v[0];
	return 0;
}

static int expect_vector(struct eval *e, const ast_node *n, double out[3])
{
	value v;
	if (eval_expr(e, n, &v))
		return -1;
	if (v.kind != V_FLOAT && !(v.kind == V_VECTOR && v.n == 3)) {
		if (v.kind == V_VECTOR)
			diag_error(n->loc, "expected a 3-component vector, found %d components", v.n);
		else
			diag_error(n->loc, "expected a vector, found %s", kind_name(v.kind));
		value_free(&v);
		return -1;
	}
	double w[5];
	widen(&v, 3, w);
	memcpy(out, w, 3 * sizeof *out);
	for (int i = 0; i < 3; i++)
		if (!isfinite(out[i])) {
			diag_error(n->loc, "vector component is not a finite number");
			return -1;
		}
	return 0;
}

static int expect_color(struct eval *e, const ast_node *n, double out[5])
{
	value v;
	if (eval_expr(e, n, &v))
		return -1;
	if (!is_numeric(v.kind)) {
		diag_error(n->loc, "expected a colour, found %s", kind_name(v.kind));
		value_free(&v);
		return -1;
	}
	widen(&v, 5, out);
	return 0;
}

/* ---- blocks ---- */

static int is_expression(const ast_node *n)
{
	return n->kind <= AST_COLOR;
}

/* POV-Ray's words for what eclat cannot render yet: a scene that uses one must
 * not render as a silently different picture. */
static void unknown_block(const ast_node *b)
{
	static const char *const pov[] = {
		"bicubic_patch", "blob", "box", "cone", "cubic", "cylinder", "difference", "disc",
		"fog", "height_field", "interior", "intersection", "isosurface", "julia_fractal",
		"lathe", "material", "media", "merge", "mesh", "mesh2", "normal", "ovus", "parametric",
		"photons", "plane", "poly", "polygon", "polynomial", "prism", "quadric", "quartic",
		"radiosity", "rainbow", "sky_sphere", "smooth_triangle", "sor", "sphere_sweep",
		"superellipsoid", "text", "torus",
	};
	for (size_t i = 0; i < sizeof pov / sizeof *pov; i++)
		if (strcmp(pov[i], b->str) == 0) {
			diag_error(b->loc, "'%s' is not supported yet", b->str);
			return;
		}
	diag_error(b->loc, "unknown keyword '%s'", b->str);
}

static int not_valid(const ast_node *item, const char *where)
{
	if (is_expression(item))
		diag_error(item->loc, "unexpected expression in %s", where);
	else if (item->kind == AST_DECLARE || item->kind == AST_INCLUDE)
		diag_error(item->loc, "directives are not supported inside %s yet", where);
	else if (item->kind == AST_BLOCK && item->kw == KW_UNKNOWN)
		unknown_block(item);
	else
		diag_error(item->loc, "'%s' is not valid in %s", ast_keyword_name(item->kw), where);
	return -1;
}

/* translate, rotate and scale: 1 when item is one (and t updated), 0 when not, -1 on error. */
static int transform_item(struct eval *e, const ast_node *item, xform *t)
{
	if (item->kind != AST_ARG ||
	    (item->kw != KW_TRANSLATE && item->kw != KW_ROTATE && item->kw != KW_SCALE))
		return 0;
	double v[3];
	if (expect_vector(e, item->kids[0], v))
		return -1;
	xform step;
	if (item->kw == KW_TRANSLATE) {
		step = scene_xform_translate(v);
	} else if (item->kw == KW_ROTATE) {
		step = scene_xform_rotate(v);
	} else {
		for (int i = 0; i < 3; i++)
			if (v[i] == 0) {
				diag_warning(item->kids[0]->loc, "scale by 0 changed to 1, as POV-Ray does");
				v[i] = 1;
			}
		step = scene_xform_scale(v);
	}
	*t = scene_xform_then(t, &step);
	return 1;
}

static int eval_material_block(struct eval *e, const ast_node *b, scene_material *m);

static void apply_pigment(scene_material *m, const double c[5])
{
	for (int i = 0; i < 5; i++)
		m->pigment[i] = (float)c[i];
}

static void apply_finish(scene_material *m, const scene_material *f)
{
	m->diffuse = f->diffuse;
	memcpy(m->ambient, f->ambient, sizeof m->ambient);
	memcpy(m->emission, f->emission, sizeof m->emission);
}

/* A positional item of a pigment, finish or texture block: a declared one of the
 * same kind (or a colour, for a pigment) that the block starts from. */
static int material_base(struct eval *e, const ast_node *b, const ast_node *item, scene_material *m)
{
	value v;
	if (eval_expr(e, item, &v))
		return -1;
	val_kind want = b->kw == KW_PIGMENT ? V_PIGMENT : b->kw == KW_FINISH ? V_FINISH : V_TEXTURE;
	if (b->kw == KW_PIGMENT && is_numeric(v.kind)) {
		double c[5];
		widen(&v, 5, c);
		apply_pigment(m, c);
		return 0;
	}
	if (v.kind != want) {
		diag_error(item->loc, "expected %s%s, found %s", kind_name(want),
		           b->kw == KW_PIGMENT ? " or a colour" : "", kind_name(v.kind));
		value_free(&v);
		return -1;
	}
	if (want == V_PIGMENT)
		apply_pigment(m, (double[5]){ v.mat.pigment[0], v.mat.pigment[1], v.mat.pigment[2],
		                              v.mat.pigment[3], v.mat.pigment[4] });
	else if (want == V_FINISH)
		apply_finish(m, &v.mat);
	else
		*m = v.mat;
	value_free(&v);
	return 0;
}

static int finish_item(struct eval *e, const ast_node *item, scene_material *m)
{
	double c[5];
	switch (item->kind == AST_ARG ? item->kw : -1) {
	case KW_DIFFUSE:
		if (expect_float(e, item->kids[0], c))
			return -1;
		m->diffuse = (float)c[0];
		return 0;
	case KW_AMBIENT:
	case KW_EMISSION:
		if (expect_color(e, item->kids[0], c))
			return -1;
		for (int i = 0; i < 3; i++)
			(item->kw == KW_AMBIENT ? m->ambient : m->emission)[i] = (float)c[i];
		return 0;
	default:
		return not_valid(item, "a finish");
	}
}

/* pigment { COLOR }, finish { ITEMS }, texture { pigment {} finish {} } */
static int eval_material_block(struct eval *e, const ast_node *b, scene_material *m)
{
	for (int i = 0; i < b->n_kids; i++) {
		const ast_node *item = b->kids[i];
		int rc;
		if (is_expression(item) && i == 0)
			rc = material_base(e, b, item, m);
		else if (b->kw == KW_FINISH)
			rc = finish_item(e, item, m);
		else if (b->kw == KW_TEXTURE && item->kind == AST_BLOCK &&
		         (item->kw == KW_PIGMENT || item->kw == KW_FINISH))
			rc = eval_material_block(e, item, m);
		else
			rc = not_valid(item, b->kw == KW_PIGMENT ? "a pigment" : "a texture");
		if (rc)
			return -1;
	}
	return 0;
}

static int is_object_kw(int kw)
{
	return kw == KW_SPHERE || kw == KW_TRIANGLE || kw == KW_UNION || kw == KW_OBJECT;
}

static int eval_object(struct eval *e, const ast_node *b, value *out);

/* The items every object accepts after its own arguments. */
/* A union's texture goes to its parts that have none of their own. This happens
 * when the union is used (placed in the scene or in another union), so that
 * object { U pigment { ... } } still changes the texture of U's bare parts. */
static void resolve_texture(value *obj)
{
	for (int i = 0; obj->compound && obj->has_mat && i < obj->n_objs; i++)
		if (!obj->objs[i].textured) {
			obj->objs[i].material = obj->mat;
			obj->objs[i].textured = true;
		}
	obj->has_mat = 0;
}

/* The items every object accepts after its own arguments: transforms, and a
 * pigment, finish or texture that changes the object's texture (a union's own). */
static int object_modifier(struct eval *e, const ast_node *item, value *obj, const char *where)
{
	xform t = scene_xform_identity();
	int rc = transform_item(e, item, &t);
	if (rc < 0)
		return -1;
	if (rc > 0) {
		for (int i = 0; i < obj->n_objs; i++)
			obj->objs[i].xf = scene_xform_then(&obj->objs[i].xf, &t);
		return 0;
	}
	if (item->kind != AST_BLOCK || (item->kw != KW_PIGMENT && item->kw != KW_FINISH && item->kw != KW_TEXTURE))
		return not_valid(item, where);
	if (!obj->compound) {
		obj->objs[0].textured = true;
		return eval_material_block(e, item, &obj->objs[0].material);
	}
	if (!obj->has_mat)
		obj->mat = scene_default_material();
	obj->has_mat = 1;
	return eval_material_block(e, item, &obj->mat);
}

/* sphere { <Center>, Radius }  triangle { <A>, <B>, <C> } */
static int eval_shape(struct eval *e, const ast_node *b, value *out)
{
	scene_object o = { .shape = b->kw == KW_SPHERE ? SHAPE_SPHERE : SHAPE_TRIANGLE,
	                   .xf = scene_xform_identity(), .material = scene_default_material(),
	                   .loc = b->loc };
	int want = o.shape == SHAPE_SPHERE ? 2 : 3, got = 0, i = 0;
	const char *where = o.shape == SHAPE_SPHERE ? "a sphere" : "a triangle";
	for (; i < b->n_kids && got < want && is_expression(b->kids[i]); i++, got++) {
		int rc = o.shape == SHAPE_SPHERE && got == 1
		       ? expect_float(e, b->kids[i], &o.radius)
		       : expect_vector(e, b->kids[i], o.p[got]);
		if (rc)
			return -1;
	}
	if (got < want) {
		diag_error(i < b->n_kids ? b->kids[i]->loc : b->loc, "%s needs %s", where,
		           o.shape == SHAPE_SPHERE ? "a centre and a radius" : "three corners");
		return -1;
	}
	*out = (value){ .kind = V_OBJECT };
	add_object(out, &o);
	for (; i < b->n_kids; i++)
		if (object_modifier(e, b->kids[i], out, where))
			return -1;
	return 0;
}

/* union { OBJECTS... [MODIFIERS...] }  object { IDENTIFIER [MODIFIERS...] } */
static int eval_compound(struct eval *e, const ast_node *b, value *out)
{
	*out = (value){ .kind = V_OBJECT };
	const char *where = b->kw == KW_UNION ? "a union" : "an object";
	int i = 0;
	if (b->kw == KW_OBJECT) {
		if (b->n_kids == 0 || !is_expression(b->kids[0])) {
			diag_error(b->loc, "object needs an object identifier first");
			return -1;
		}
		if (eval_expr(e, b->kids[0], out))
			return -1;
		if (out->kind != V_OBJECT) {
			diag_error(b->kids[0]->loc, "expected an object, found %s", kind_name(out->kind));
			value_free(out);
			return -1;
		}
		i = 1;
	}
	int modifiers_seen = 0;
	if (b->kw == KW_UNION)
		out->compound = 1;
	for (; i < b->n_kids; i++) {
		const ast_node *item = b->kids[i];
		if (b->kw == KW_UNION && item->kind == AST_BLOCK && is_object_kw(item->kw)) {
			if (modifiers_seen) {
				diag_error(item->loc, "the objects of a union come before its modifiers");
				return -1;
			}
			value part;
			if (eval_object(e, item, &part))
				return -1;
			resolve_texture(&part);
			for (int k = 0; k < part.n_objs; k++)
				add_object(out, &part.objs[k]);
			value_free(&part);
			continue;
		}
		modifiers_seen = 1;
		if (object_modifier(e, item, out, where))
			return -1;
	}
	return 0;
}

static int eval_object(struct eval *e, const ast_node *b, value *out)
{
	if (b->kw == KW_SPHERE || b->kw == KW_TRIANGLE)
		return eval_shape(e, b, out);
	return eval_compound(e, b, out);
}

/* camera { [perspective] [location V] [direction V] [right V] [up V] [sky V]
 *          [angle F] [look_at V] [TRANSFORMS...] }
 * Applied in POV-Ray 3.7's fixed order whatever the order in the file: the
 * vectors, then angle, then look_at, then the transforms. */
static int eval_camera(struct eval *e, const ast_node *b)
{
	scene_camera c = scene_default_camera();
	double sky[3] = { 0, 1, 0 }, look_at[3], angle = -1;
	int has_look_at = 0;
	xform t = scene_xform_identity();
	c.loc = b->loc;
	for (int i = 0; i < b->n_kids; i++) {
		const ast_node *item = b->kids[i];
		int rc = transform_item(e, item, &t);
		if (rc < 0)
			return -1;
		if (rc > 0 || (item->kind == AST_FLAG && item->kw == KW_PERSPECTIVE))
			continue;
		double *dst = NULL;
		switch (item->kind == AST_ARG ? item->kw : -1) {
		case KW_LOCATION: dst = c.location; break;
		case KW_DIRECTION: dst = c.direction; break;
		case KW_RIGHT: dst = c.right; break;
		case KW_UP: dst = c.up; break;
		case KW_SKY: dst = sky; break;
		case KW_LOOK_AT: dst = look_at; has_look_at = 1; break;
		case KW_ANGLE:
			if (expect_float(e, item->kids[0], &angle))
				return -1;
			if (angle <= 0 || angle >= 180) {
				diag_error(item->kids[0]->loc, "camera angle must be between 0 and 180 degrees");
				return -1;
			}
			continue;
		default:
			return not_valid(item, "a camera");
		}
		if (expect_vector(e, item->kids[0], dst))
			return -1;
	}
	if (angle > 0) {
		double dl = sqrt(c.direction[0] * c.direction[0] + c.direction[1] * c.direction[1] +
		                 c.direction[2] * c.direction[2]);
		double rl = sqrt(c.right[0] * c.right[0] + c.right[1] * c.right[1] + c.right[2] * c.right[2]);
		double want = rl / tan(angle * M_PI / 360.0) / 2.0;
		for (int k = 0; k < 3 && dl > 0; k++)
			c.direction[k] *= want / dl;
	}
	if (has_look_at && scene_camera_look_at(&c, look_at, sky) != 0) {
		diag_error(b->loc, "camera location and look_at point must be different");
		return -1;
	}
	scene_xform_point(&t, c.location, c.location);
	scene_xform_vector(&t, c.direction, c.direction);
	scene_xform_vector(&t, c.right, c.right);
	scene_xform_vector(&t, c.up, c.up);
	e->s->camera = c;
	return 0;
}

/* light_source { <Location>, COLOR [TRANSFORMS...] } */
static int eval_light(struct eval *e, const ast_node *b)
{
	scene_light l = scene_default_light();
	l.loc = b->loc;
	double pos[3], col[5];
	if (b->n_kids < 2 || !is_expression(b->kids[0]) || !is_expression(b->kids[1])) {
		diag_error(b->loc, "light_source needs a location and a colour");
		return -1;
	}
	if (expect_vector(e, b->kids[0], pos) || expect_color(e, b->kids[1], col))
		return -1;
	xform t = scene_xform_identity();
	for (int i = 2; i < b->n_kids; i++) {
		int rc = transform_item(e, b->kids[i], &t);
		if (rc < 0)
			return -1;
		if (rc == 0)
			return not_valid(b->kids[i], "a light_source");
	}
	scene_xform_point(&t, pos, l.position);
	for (int i = 0; i < 3; i++)
		l.color[i] = (float)col[i];
	scene_add_light(e->s, &l);
	return 0;
}

static int eval_background(struct eval *e, const ast_node *b)
{
	double c[5];
	if (b->n_kids != 1 || !is_expression(b->kids[0])) {
		diag_error(b->loc, "background needs one colour");
		return -1;
	}
	if (expect_color(e, b->kids[0], c))
		return -1;
	for (int i = 0; i < 3; i++)
		e->s->background[i] = (float)c[i];
	return 0;
}

static int eval_global_settings(struct eval *e, const ast_node *b)
{
	for (int i = 0; i < b->n_kids; i++) {
		const ast_node *item = b->kids[i];
		double f;
		if (item->kind != AST_ARG || item->kw != KW_MAX_TRACE_LEVEL)
			return not_valid(item, "global_settings");
		if (expect_float(e, item->kids[0], &f))
			return -1;
		if (f < 1 || f > 256) {
			diag_error(item->kids[0]->loc, "max_trace_level must be between 1 and 256");
			return -1;
		}
		e->s->max_trace_level = (int)f;
	}
	return 0;
}

/* #declare NAME = VALUE: a value or a pigment, finish, texture or object block. */
static int eval_declare(struct eval *e, const ast_node *d)
{
	const ast_node *rhs = d->kids[0];
	value v;
	if (rhs->kind != AST_BLOCK) {
		if (eval_expr(e, rhs, &v))
			return -1;
	} else if (is_object_kw(rhs->kw)) {
		if (eval_object(e, rhs, &v))
			return -1;
	} else if (rhs->kw == KW_PIGMENT || rhs->kw == KW_FINISH || rhs->kw == KW_TEXTURE) {
		v = (value){ .kind = rhs->kw == KW_PIGMENT ? V_PIGMENT : rhs->kw == KW_FINISH ? V_FINISH : V_TEXTURE,
		             .mat = scene_default_material() };
		if (eval_material_block(e, rhs, &v.mat))
			return -1;
	} else {
		diag_error(rhs->loc, "a %s cannot be declared yet", ast_keyword_name(rhs->kw));
		return -1;
	}
	declare(e, d->str, v);
	return 0;
}

static int eval_items(struct eval *e, const ast_node *file);

/* #include "FILE": the path is relative to the including file's folder. */
static int eval_include(struct eval *e, const ast_node *inc)
{
	value v;
	if (eval_expr(e, inc->kids[0], &v))
		return -1;
	if (v.kind != V_STRING) {
		diag_error(inc->kids[0]->loc, "expected a file name string, found %s", kind_name(v.kind));
		value_free(&v);
		return -1;
	}
	if (e->include_depth >= MAX_INCLUDE_DEPTH) {
		diag_error(inc->loc, "#include nested more than %d deep (an include cycle?)", MAX_INCLUDE_DEPTH);
		value_free(&v);
		return -1;
	}
	const char *from = diag_source_name(inc->loc.file);
	const char *slash = strrchr(from, '/');
	char *path = NULL;
	if (v.str[0] == '/' || !slash)
		path = strdup(v.str);
	else if (asprintf(&path, "%.*s/%s", (int)(slash - from), from, v.str) < 0)
		path = NULL;
	value_free(&v);
	if (!path) {
		fprintf(stderr, "eclat: out of memory\n");
		exit(1);
	}
	ast_node *tree = parse_file(path, inc->kids[0]->loc);
	free(path);
	if (!tree)
		return -1;
	e->include_depth++;
	int rc = eval_items(e, tree);
	e->include_depth--;
	ast_free(tree);
	return rc;
}

static int eval_statement(struct eval *e, const ast_node *item)
{
	if (item->kind == AST_DECLARE)
		return eval_declare(e, item);
	if (item->kind == AST_INCLUDE)
		return eval_include(e, item);
	if (item->kind != AST_BLOCK)
		return not_valid(item, "the scene (expected an object, camera, light_source or directive)");
	switch (item->kw) {
	case KW_CAMERA: return eval_camera(e, item);
	case KW_LIGHT_SOURCE: return eval_light(e, item);
	case KW_BACKGROUND: return eval_background(e, item);
	case KW_GLOBAL_SETTINGS: return eval_global_settings(e, item);
	default: break;
	}
	if (!is_object_kw(item->kw))
		return not_valid(item, "the scene (expected an object, camera, light_source or directive)");
	value v;
	if (eval_object(e, item, &v))
		return -1;
	resolve_texture(&v);
	for (int i = 0; i < v.n_objs; i++)
		scene_add_object(e->s, &v.objs[i]);
	value_free(&v);
	return 0;
}

/* Statements are independent, so an error in one does not stop the others from
 * being checked: the user sees every error of the file in one run. */
static int eval_items(struct eval *e, const ast_node *file)
{
	int rc = 0;
	for (int i = 0; i < file->n_kids; i++)
		if (eval_statement(e, file->kids[i]))
			rc = -1;
	return rc;
}

int eval_scene(const ast_node *root, scene *s)
{
	struct eval e = { .s = s };
	declare_builtins(&e);
	int rc = eval_items(&e, root);
	while (e.symbols) {
		struct symbol *next = e.symbols->next;
		value_free(&e.symbols->val);
		free(e.symbols->name);
		free(e.symbols);
		e.symbols = next;
	}
	return rc;
}
