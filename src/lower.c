/* lower.c: bakes transforms into world-space primitives, builds the BVH and
 * reorders the primitives into its leaf order, so a leaf is a contiguous range. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lower.h"

/* The device reads these structs byte for byte: the layouts must not drift. */
_Static_assert(sizeof(float4) == 16, "float4 is 16 bytes");
_Static_assert(sizeof(bvh_node) == 32, "bvh_node is 32 bytes");
_Static_assert(offsetof(bvh_node, max_x) == 16, "bvh_node max at 16");
_Static_assert(sizeof(dev_prim) == 64, "dev_prim is 64 bytes");
_Static_assert(offsetof(dev_prim, type) == 48, "dev_prim ints at 48");
_Static_assert(sizeof(dev_material) == 32, "dev_material is 32 bytes");
_Static_assert(sizeof(dev_light) == 32, "dev_light is 32 bytes");
_Static_assert(sizeof(dev_params) == 112, "dev_params is 112 bytes");
_Static_assert(offsetof(dev_params, width) == 80, "dev_params ints at 80");

static float4 f4(const double v[3], double w)
{
	return (float4){ (float)v[0], (float)v[1], (float)v[2], (float)w };
}

/* The uniform scale of a similarity transform, or -1 when the transform
 * stretches unevenly (a sphere would become an ellipsoid). */
static double uniform_scale(const xform *t)
{
	double len[3], dots[3];
	for (int j = 0; j < 3; j++)
		len[j] = sqrt(t->m[0][j] * t->m[0][j] + t->m[1][j] * t->m[1][j] + t->m[2][j] * t->m[2][j]);
	for (int j = 0; j < 3; j++) {
		int k = (j + 1) % 3;
		dots[j] = t->m[0][j] * t->m[0][k] + t->m[1][j] * t->m[1][k] + t->m[2][j] * t->m[2][k];
	}
	for (int j = 0; j < 3; j++)
		if (fabs(len[j] - len[0]) > 1e-9 * len[0] || fabs(dots[j]) > 1e-9 * len[0] * len[0])
			return -1;
	return len[0];
}

static int lower_sphere(const scene_object *o, dev_prim *p)
{
	double s = uniform_scale(&o->xf), c[3];
	if (s < 0) {
		diag_error(o->loc, "a sphere scaled unevenly (an ellipsoid) is not supported yet");
		return -1;
	}
	double r = o->radius * s;
	if (!(r > 0) || !isfinite(r)) {
		diag_warning(o->loc, "sphere of radius %g skipped", o->radius);
		return 0;
	}
	scene_xform_point(&o->xf, o->p[0], c);
	*p = (dev_prim){ .a = f4(c, r), .type = PRIM_SPHERE };
	return 1;
}

static int lower_triangle(const scene_object *o, dev_prim *p, int *n_degenerate)
{
	double v[3][3];
	for (int i = 0; i < 3; i++)
		scene_xform_point(&o->xf, o->p[i], v[i]);
	double e1[3], e2[3];
	for (int k = 0; k < 3; k++) {
		e1[k] = v[1][k] - v[0][k];
		e2[k] = v[2][k] - v[0][k];
	}
	double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
	                e1[0] * e2[1] - e1[1] * e2[0] };
	if (n[0] == 0 && n[1] == 0 && n[2] == 0) {
		if ((*n_degenerate)++ == 0)
			diag_warning(o->loc, "triangle with no area skipped");
		return 0;
	}
	*p = (dev_prim){ .a = f4(v[0], 0), .b = f4(e1, 0), .c = f4(e2, 0), .type = PRIM_TRIANGLE };
	return 1;
}

static dev_material lower_material(const scene_material *m)
{
	float4 albedo = { m->pigment[0] * m->diffuse, m->pigment[1] * m->diffuse,
	                  m->pigment[2] * m->diffuse, 0 };
	float4 emission = { m->pigment[0] * m->emission[0], m->pigment[1] * m->emission[1],
	                    m->pigment[2] * m->emission[2], 0 };
	return (dev_material){ albedo, emission };
}

static bvh_box prim_box(const dev_prim *p)
{
	bvh_box b;
	if (p->type == PRIM_SPHERE) {
		float c[3] = { p->a.x, p->a.y, p->a.z };
		for (int k = 0; k < 3; k++) {
			b.min[k] = c[k] - p->a.w;
			b.max[k] = c[k] + p->a.w;
		}
		return b;
	}
	float v[3][3] = { { p->a.x, p->a.y, p->a.z },
	                  { p->a.x + p->b.x, p->a.y + p->b.y, p->a.z + p->b.z },
	                  { p->a.x + p->c.x, p->a.y + p->c.y, p->a.z + p->c.z } };
	for (int k = 0; k < 3; k++) {
		b.min[k] = fminf(v[0][k], fminf(v[1][k], v[2][k]));
		b.max[k] = fmaxf(v[0][k], fmaxf(v[1][k], v[2][k]));
	}
	return b;
}

static void lower_camera(const scene *s, dev_params *p)
{
	const scene_camera *c = &s->camera;
	p->cam_location = f4(c->location, 0);
	p->cam_direction = f4(c->direction, 0);
	p->cam_right = f4(c->right, 0);
	p->cam_up = f4(c->up, 0);
	p->background = (float4){ s->background[0], s->background[1], s->background[2], 0 };
}

static void *xmalloc(size_t n)
{
	void *p = malloc(n ? n : 1);
	if (!p) {
		fprintf(stderr, "eclat: out of memory\n");
		exit(1);
	}
	return p;
}

int lower_scene(const scene *s, lower_result *out)
{
	memset(out, 0, sizeof *out);
	dev_prim *prims = xmalloc(s->n_objects * sizeof *prims);
	out->materials = xmalloc(s->n_objects * sizeof *out->materials);
	int n = 0, n_degenerate = 0, rc = 0;
	for (int i = 0; i < s->n_objects; i++) {
		const scene_object *o = &s->objects[i];
		int kept = o->shape == SHAPE_SPHERE ? lower_sphere(o, &prims[n])
		                                    : lower_triangle(o, &prims[n], &n_degenerate);
		if (kept < 0)
			rc = -1;
		if (kept <= 0)
			continue;
		prims[n].material = out->n_materials;
		prims[n].object = i;
		out->materials[out->n_materials++] = lower_material(&o->material);
		n++;
	}
	if (n_degenerate > 1)
		diag_warning(SRC_NOWHERE, "%d triangles with no area skipped in all", n_degenerate);

	out->lights = xmalloc(s->n_lights * sizeof *out->lights);
	for (int i = 0; i < s->n_lights; i++) {
		const scene_light *l = &s->lights[i];
		double c[3] = { l->color[0], l->color[1], l->color[2] };
		out->lights[i] = (dev_light){ f4(l->position, 0), f4(c, 0) };
	}
	out->n_lights = s->n_lights;
	lower_camera(s, &out->params);

	bvh_box *boxes = xmalloc(n * sizeof *boxes);
	for (int i = 0; i < n; i++)
		boxes[i] = prim_box(&prims[i]);
	if (rc == 0 && bvh_build(boxes, n, &out->bvh) != 0) {
		fprintf(stderr, "eclat: out of memory building the BVH\n");
		rc = -1;
	}
	free(boxes);
	if (rc == 0 && out->bvh.depth > BVH_STACK_SIZE) {
		diag_error(SRC_NOWHERE, "the BVH is %d levels deep, more than the %d the kernels can traverse",
		           out->bvh.depth, BVH_STACK_SIZE);
		rc = -1;
	}
	if (rc == 0) {
		out->prims = xmalloc(n * sizeof *out->prims);
		for (int i = 0; i < n; i++)
			out->prims[i] = prims[out->bvh.prim_index[i]];
		out->n_prims = n;
	}
	free(prims);
	return rc;
}

void lower_free(lower_result *r)
{
	free(r->prims);
	free(r->materials);
	free(r->lights);
	bvh_free(&r->bvh);
	memset(r, 0, sizeof *r);
}
