/* eval_value.c: the values of the language: copying, freeing, promotion. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval_int.h"

void *eval_xrealloc(void *p, size_t size)
{
	p = realloc(p, size ? size : 1);
	if (!p) {
		fprintf(stderr, "eclat: out of memory\n");
		diag_exit(1);
	}
	return p;
}

char *eval_xstrdup(const char *s)
{
	size_t n = strlen(s) + 1;
	return memcpy(eval_xrealloc(NULL, n), s, n);
}

const char *eval_kind_name(val_kind k)
{
	static const char *const names[] = { /* ORDER val_kind */
		"nothing", "a float", "a vector", "a colour", "a string", "an object", "a pigment",
		"a finish", "a texture", "a normal", "an interior", "a material", "a map",
		"a transform", "a camera", "an array", "a macro", "a function", "a spline", "a fog", "a media",
		"something else",
	};
	return names[k];
}

static void array_free(struct array *a)
{
	if (!a)
		return;
	for (int i = 0; i < a->n; i++)
		eval_value_free(&a->elems[i]);
	free(a->elems);
	free(a);
}

void eval_value_free(value *v)
{
	free(v->str);
	eval_objval_free(v->obj);
	free(v->cam);
	free(v->fog);
	array_free(v->arr);
	v->str = NULL;
	v->fog = NULL;
	v->obj = NULL;
	v->cam = NULL;
	v->arr = NULL;
}

static struct array *array_copy(const struct array *a)
{
	struct array *c = eval_xrealloc(NULL, sizeof *c);
	*c = *a;
	c->elems = eval_xrealloc(NULL, a->n * sizeof *c->elems);
	for (int i = 0; i < a->n; i++)
		c->elems[i] = eval_value_copy(&a->elems[i]);
	return c;
}

static void *dup_bytes(const void *p, size_t n)
{
	return n ? memcpy(eval_xrealloc(NULL, n), p, n) : NULL;
}

static struct objval *objval_copy(const struct objval *o)
{
	struct objval *c = dup_bytes(o, sizeof *o);
	c->objs = dup_bytes(o->objs, o->n_objs * sizeof *o->objs);
	c->cap_objs = o->n_objs;
	c->csgs = dup_bytes(o->csgs, o->n_csgs * sizeof *o->csgs);
	for (int i = 0; i < o->n_csgs; i++)
		c->csgs[i].ops = dup_bytes(o->csgs[i].ops, o->csgs[i].n_ops * sizeof *o->csgs[i].ops);
	c->bound = o->bound ? objval_copy(o->bound) : NULL;
	c->lights = dup_bytes(o->lights, o->n_lights * sizeof *o->lights);
	for (int i = 0; i < o->n_lights; i++)
		c->lights[i].looks = dup_bytes(o->lights[i].looks, o->lights[i].n_looks * sizeof *o->lights[i].looks);
	return c;
}

value eval_value_copy(const value *v)
{
	value c = *v;
	c.str = v->str ? eval_xstrdup(v->str) : NULL;
	c.obj = v->obj ? objval_copy(v->obj) : NULL;
	c.cam = v->cam ? dup_bytes(v->cam, sizeof *v->cam) : NULL;
	c.fog = v->fog ? dup_bytes(v->fog, sizeof *v->fog) : NULL;
	c.arr = v->arr ? array_copy(v->arr) : NULL;
	return c;
}

value eval_float(double f)
{
	return (value){ .kind = V_FLOAT, .n = 1, .v = { f } };
}

value eval_vector3(const double v[3])
{
	return (value){ .kind = V_VECTOR, .n = 3, .v = { v[0], v[1], v[2] } };
}

bool eval_is_numeric(val_kind k)
{
	return k == V_FLOAT || k == V_VECTOR || k == V_COLOR;
}

void eval_widen(const value *v, int n, double out[5])
{
	for (int i = 0; i < 5; i++)
		out[i] = v->kind == V_FLOAT ? (i < n ? v->v[0] : 0) : (i < v->n ? v->v[i] : 0);
}

struct objval *eval_objval_new(src_loc loc)
{
	struct objval *o = eval_xrealloc(NULL, sizeof *o);
	*o = (struct objval){ .loc = loc };
	return o;
}

/* Grows objs geometrically: a union of thousands of objects must not copy its
 * list once per object (a sanitizer's realloc always copies). */
void eval_objval_add(struct objval *o, const scene_object *so)
{
	if (o->n_objs >= o->cap_objs) {
		int cap = o->cap_objs > 0 ? 2 * o->cap_objs : 8;
		if (cap < o->n_objs + 1)
			cap = o->n_objs + 1;
		o->objs = eval_xrealloc(o->objs, (size_t)cap * sizeof *o->objs);
		o->cap_objs = cap;
	}
	o->objs[o->n_objs++] = *so;
}

/* Takes the looks_like array of l. */
void eval_objval_add_light(struct objval *o, const struct lightval *l)
{
	o->lights = eval_xrealloc(o->lights, (o->n_lights + 1) * sizeof *o->lights);
	o->lights[o->n_lights++] = *l;
}

void eval_objval_merge(struct objval *dst, const struct objval *src)
{
	int shift = dst->n_objs;
	dst->csgs = eval_xrealloc(dst->csgs, (dst->n_csgs + src->n_csgs + 1) * sizeof *dst->csgs);
	for (int i = 0; i < src->n_csgs; i++) {
		struct objcsg g = src->csgs[i];
		g.first += shift;
		g.ops = dup_bytes(g.ops, g.n_ops * sizeof *g.ops);
		dst->csgs[dst->n_csgs++] = g;
	}
	for (int i = 0; i < src->n_objs; i++)
		eval_objval_add(dst, &src->objs[i]);
	for (int i = 0; i < src->n_lights; i++) {
		struct lightval l = src->lights[i];
		l.looks = dup_bytes(l.looks, l.n_looks * sizeof *l.looks);
		eval_objval_add_light(dst, &l);
	}
	if (src->unsupported && !dst->unsupported) {
		dst->unsupported = src->unsupported;
		dst->unsupported_loc = src->unsupported_loc;
	}
}

void eval_objval_free(struct objval *o)
{
	if (!o)
		return;
	for (int i = 0; i < o->n_lights; i++)
		free(o->lights[i].looks);
	free(o->lights);
	for (int i = 0; i < o->n_csgs; i++)
		free(o->csgs[i].ops);
	free(o->csgs);
	eval_objval_free(o->bound);
	free(o->objs);
	free(o);
}
